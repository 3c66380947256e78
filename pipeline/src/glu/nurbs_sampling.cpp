#include "glu/nurbs_sampling.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace glass::gl::glu {

namespace {

constexpr int kMaxSteps = 1024;

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double secondDifference(const std::array<double, 3>& a, const std::array<double, 3>& b,
                        const std::array<double, 3>& c) {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double d = a[k] - 2.0 * b[k] + c[k];
    sum += d * d;
  }
  return std::sqrt(sum);
}

bool isObjectSpace(GLenum method) {
  return method == GLU_OBJECT_PATH_LENGTH || method == GLU_OBJECT_PARAMETRIC_ERROR;
}

bool isPathLength(GLenum method) {
  return method == GLU_PATH_LENGTH || method == GLU_OBJECT_PATH_LENGTH;
}

// The step for a row of points spanning `range` of parameter, by the sampling method, with the
// surface factor 1/2 on path lengths.
double rowStep(const std::vector<const std::array<double, 3>*>& row, double range, GLenum method,
               double tolerance, double parametricTolerance, bool surface) {
  const int k = static_cast<int>(row.size());
  if (isPathLength(method)) {
    double longest = 0.0;
    for (int i = 0; i + 1 < k; ++i) longest = std::max(longest, distance(*row[i], *row[i + 1]));
    const double velocity = (k - 1) / range * longest;
    if (velocity <= 0.0) return range;
    return std::min(range, tolerance / ((surface ? 2.0 : 1.0) * velocity));
  }
  double largest = 0.0;
  for (int i = 0; i + 2 < k; ++i) {
    largest = std::max(largest, secondDifference(*row[i], *row[i + 1], *row[i + 2]));
  }
  const double acceleration = (k - 1) * (k - 2) / (range * range) * largest;
  if (acceleration <= 0.0) return range;
  return std::min(range, std::sqrt(8.0 * parametricTolerance / acceleration));
}

}  // namespace

int stepCount(double range, double step) {
  if (!(step > 0.0) || !(range > 0.0)) return 1;
  const double n = std::ceil(range / step - 1e-9);
  return static_cast<int>(std::clamp(n, 1.0, static_cast<double>(kMaxSteps)));
}

NurbsSampler::NurbsSampler(const GLUnurbs& nurb) : nurb_(nurb) {
  float modelview[16], projection[16];
  int viewport[4];
  if (nurb.autoLoadMatrix) {
    glGetFloatv(GL_MODELVIEW_MATRIX, modelview);
    glGetFloatv(GL_PROJECTION_MATRIX, projection);
    glGetIntegerv(GL_VIEWPORT, viewport);
  } else {
    std::copy_n(nurb.modelview, 16, modelview);
    std::copy_n(nurb.projection, 16, projection);
    std::copy_n(nurb.viewport, 4, viewport);
  }
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += double(projection[k * 4 + r]) * modelview[c * 4 + k];
      clip_[c * 4 + r] = sum;
    }
  }
  halfWidth_ = 0.5 * viewport[2];
  halfHeight_ = 0.5 * viewport[3];
}

bool NurbsSampler::measure(const double* p, int dimension, double out[3]) const {
  const double w = dimension == 4 ? p[3] : 1.0;
  if (isObjectSpace(nurb_.samplingMethod)) {
    if (w == 0.0) return false;
    for (int k = 0; k < 3; ++k) out[k] = p[k] / w;
    return true;
  }
  double clip[4];
  for (int r = 0; r < 4; ++r) {
    clip[r] = clip_[0 * 4 + r] * p[0] + clip_[1 * 4 + r] * p[1] + clip_[2 * 4 + r] * p[2] +
              clip_[3 * 4 + r] * w;
  }
  if (!(clip[3] > 0.0)) return false;
  out[0] = clip[0] / clip[3] * halfWidth_;
  out[1] = clip[1] / clip[3] * halfHeight_;
  out[2] = 0.0;
  return true;
}

bool NurbsSampler::measureAll(const std::vector<double>& points, int dimension,
                              std::vector<std::array<double, 3>>& out) const {
  const size_t count = points.size() / static_cast<size_t>(dimension);
  out.resize(count);
  for (size_t i = 0; i < count; ++i) {
    if (!measure(&points[i * dimension], dimension, out[i].data())) return false;
  }
  return true;
}

double NurbsSampler::curveStep(const std::vector<double>& points, int order, int dimension,
                               double range) const {
  if (nurb_.samplingMethod == GLU_DOMAIN_DISTANCE) return 1.0 / nurb_.uStep;
  std::vector<std::array<double, 3>> measured;
  if (!measureAll(points, dimension, measured)) return range / nurb_.uStep;
  std::vector<const std::array<double, 3>*> row;
  for (int i = 0; i < order; ++i) row.push_back(&measured[i]);
  return rowStep(row, range, nurb_.samplingMethod, nurb_.samplingTolerance,
                 nurb_.parametricTolerance, false);
}

std::array<double, 2> NurbsSampler::surfaceSteps(const std::vector<double>& points, int uOrder,
                                                 int vOrder, int dimension, double uRange,
                                                 double vRange) const {
  if (nurb_.samplingMethod == GLU_DOMAIN_DISTANCE) return {1.0 / nurb_.uStep, 1.0 / nurb_.vStep};
  std::vector<std::array<double, 3>> measured;
  if (!measureAll(points, dimension, measured)) {
    return {uRange / nurb_.uStep, vRange / nurb_.vStep};
  }
  // The smallest step over every row of the net in each direction.
  std::array<double, 2> steps{uRange, vRange};
  std::vector<const std::array<double, 3>*> row;
  for (int j = 0; j < vOrder; ++j) {
    row.clear();
    for (int i = 0; i < uOrder; ++i) row.push_back(&measured[i * vOrder + j]);
    steps[0] = std::min(steps[0], rowStep(row, uRange, nurb_.samplingMethod,
                                          nurb_.samplingTolerance, nurb_.parametricTolerance,
                                          true));
  }
  for (int i = 0; i < uOrder; ++i) {
    row.clear();
    for (int j = 0; j < vOrder; ++j) row.push_back(&measured[i * vOrder + j]);
    steps[1] = std::min(steps[1], rowStep(row, vRange, nurb_.samplingMethod,
                                          nurb_.samplingTolerance, nurb_.parametricTolerance,
                                          true));
  }
  return steps;
}

bool NurbsSampler::outsideView(const std::vector<double>& points, int dimension) const {
  const size_t count = points.size() / static_cast<size_t>(dimension);
  // For each of the six planes -w <= x, y, z <= w: are all points beyond it?
  for (int plane = 0; plane < 6; ++plane) {
    const int axis = plane / 2;
    const double sign = plane % 2 == 0 ? 1.0 : -1.0;
    bool allOutside = true;
    for (size_t i = 0; i < count && allOutside; ++i) {
      const double* p = &points[i * dimension];
      const double w = dimension == 4 ? p[3] : 1.0;
      double clip[4];
      for (int r = 0; r < 4; ++r) {
        clip[r] = clip_[r] * p[0] + clip_[4 + r] * p[1] + clip_[8 + r] * p[2] + clip_[12 + r] * w;
      }
      allOutside = sign * clip[axis] > clip[3];
    }
    if (allOutside) return true;
  }
  return false;
}

}  // namespace glass::gl::glu
