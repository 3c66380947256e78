#include "glass/course/ifs_picture.h"

#include <GL/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace glass::course {

namespace g = glass::geometry;

namespace {

constexpr int kMaxDepth = 30;  // one modelview matrix per level; GL promises 32

// Listing 4 on GL's matrix stack: the recursion of g::expandIfs, each step a GL call.
class GlMatrixStack final : public g::IfsMatrixStackVisitor {
 public:
  explicit GlMatrixStack(const g::IteratedFunctionSystem& ifs) : ifs_(ifs) {}

  void pushMatrix() override { glPushMatrix(); }
  void multiplyMatrix(const g::Affine2& map) override {
    const glm::dmat4 m = map.toMatrix4();
    glMultMatrixd(glm::value_ptr(m));
  }
  void popMatrix() override { glPopMatrix(); }
  void drawBase(int part) override {
    if (part < 0) {
      glColor3f(1.0f, 1.0f, 1.0f);  // depth 0: no map applied yet, Listing 5's white
    } else {
      const g::IfsColor c = g::partColor(ifs_, static_cast<std::size_t>(part));
      glColor3f(c.r, c.g, c.b);
    }
    glBegin(GL_POLYGON);
    for (const glm::dvec2& corner : ifs_.base) glVertex2d(corner.x, corner.y);
    glEnd();
  }

 private:
  const g::IteratedFunctionSystem& ifs_;
};

}  // namespace

int defaultIfsDepth(const g::IteratedFunctionSystem& ifs, int pixels, std::uint64_t budget) {
  // The largest singular value of each linear part: how much the map can stretch a length.
  double stretch = 0.0;
  for (const g::IfsMap& map : ifs.maps) {
    const auto& m = map.transform.m;
    const double a = m[0][0], b = m[0][1], c = m[1][0], d = m[1][1];
    // Eigenvalues of L^T L: (t +- sqrt(t^2 - 4 det^2)) / 2 with t = a^2 + b^2 + c^2 + d^2.
    const double t = a * a + b * b + c * c + d * d, det = a * d - b * c;
    stretch = std::max(stretch, std::sqrt((t + std::sqrt(std::max(0.0, t * t - 4 * det * det))) / 2));
  }
  // The base figure fills about the window, `pixels` across; go deeper while the slowest copies
  // stay at least three pixels across, so that the holes of the fractal still show.
  double size = std::max(pixels, 1);
  int depth = 0;
  while (depth < kMaxDepth && size * stretch >= 3.0 && g::ifsBaseCopies(ifs, depth + 1) <= budget) {
    ++depth;
    size *= stretch;
  }
  return depth;
}

std::string checkIfsPicture(const g::IteratedFunctionSystem& ifs, const IfsPicture& picture) {
  if (ifs.maps.empty()) return "the IFS has no maps";
  if (picture.method == IfsPicture::Method::Depth) {
    if (picture.depth < 0 || picture.depth > kMaxDepth) {
      return std::string("the depth must lie in 0..") + std::to_string(kMaxDepth) + " (one matrix on GL's stack per level)";
    }
    const std::uint64_t copies = g::ifsBaseCopies(ifs, picture.depth);
    if (copies > g::kMaxIfsBaseCopies) {
      return std::string("depth ") + std::to_string(picture.depth) + " would draw " + std::to_string(ifs.maps.size()) + "^" +
             std::to_string(picture.depth) + " base figures, more than the limit of " +
             std::to_string(g::kMaxIfsBaseCopies) + "; lower the depth";
    }
  } else {
    if (picture.points == 0 || picture.points > g::kMaxChaosGamePoints) {
      return std::string("the number of points must lie in 1..") + std::to_string(g::kMaxChaosGamePoints);
    }
    if (!g::chaosGameProbabilities(ifs)) return "the maps' probabilities are not usable (give all or none, >= 0)";
  }
  return {};
}

void drawIfsPicture(const g::IteratedFunctionSystem& ifs, const IfsPicture& picture) {
  // Listing 5's resizeWindow: the window widened along one axis to the viewport's shape.
  const g::IfsWindow window =
      g::fitWindowToAspect(ifs.window ? *ifs.window : g::attractorWindow(ifs), picture.width, picture.height);
  glViewport(0, 0, picture.width, picture.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(window.xMin, window.xMax, window.yMin, window.yMax, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);  // a reflecting map turns the base figure over
  glShadeModel(GL_FLAT);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  if (picture.method == IfsPicture::Method::Depth) {
    GlMatrixStack stack(ifs);
    g::expandIfs(ifs, picture.depth, stack);
    return;
  }
  const auto probabilities = g::chaosGameProbabilities(ifs);
  if (!probabilities) return;
  glPointSize(1.0f);
  glBegin(GL_POINTS);
  int currentPart = -1;
  g::chaosGame(ifs, *probabilities, picture.points, picture.seed, [&](const glm::dvec2& p, int part) {
    if (part != currentPart) {
      const g::IfsColor c = g::partColor(ifs, static_cast<std::size_t>(part));
      glColor3f(c.r, c.g, c.b);
      currentPart = part;
    }
    glVertex2d(p.x, p.y);
  });
  glEnd();
}

}  // namespace glass::course
