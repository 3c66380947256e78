// gluCylinder (GLU 1.3, section 6.8): a cylinder (or cone, or truncated cone) along the z axis,
// from radius `base` at z = 0 to radius `top` at z = height.
//
// Slice boundary i sits at theta_i = 2 pi i / slices from +y towards +x; stack boundary j at
// z_j = j height / stacks with radius r_j = base - (base - top) j / stacks. The side's normal
// leans along z by the slope of the cone: with L = sqrt((base - top)^2 + height^2),
//   n = (height / L sin theta,  height / L cos theta,  (base - top) / L)
// (x and y reversed for GLU_INSIDE). Flat normals use the angle half a slice back, at the middle
// of the face. Texture coordinates run s = 1 - i / slices, t = j / stacks.
#include <cmath>
#include <vector>

#include "glu/quadric_tables.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl::glu {
namespace {

class CylinderTables {
 public:
  CylinderTables(double base, double height, int slices, int stacks, bool outside,
                 float deltaRadius, float length)
      : base_(base), height_(height), slices_(slices), stacks_(stacks), deltaRadius_(deltaRadius) {
    zNormal_ = deltaRadius / length;
    const float xyRatio = static_cast<float>(height / length);
    const float signedRatio = outside ? xyRatio : -xyRatio;
    sin_.resize(slices + 1);
    cos_.resize(slices + 1);
    normSin_.resize(slices + 1);
    normCos_.resize(slices + 1);
    normMidSin_.resize(slices + 1);
    normMidCos_.resize(slices + 1);
    for (int i = 0; i < slices; ++i) {
      const double angle = static_cast<float>(2.0 * kPi * i / slices);
      sin_[i] = static_cast<float>(portable::sin(angle));
      cos_[i] = static_cast<float>(portable::cos(angle));
      normSin_[i] = static_cast<float>(signedRatio * portable::sin(angle));
      normCos_[i] = static_cast<float>(signedRatio * portable::cos(angle));
      const double mid = static_cast<float>(2.0 * kPi * (i - 0.5) / slices);
      normMidSin_[i] = static_cast<float>(signedRatio * portable::sin(mid));
      normMidCos_[i] = static_cast<float>(signedRatio * portable::cos(mid));
    }
    sin_[slices] = sin_[0];
    cos_[slices] = cos_[0];
    normSin_[slices] = normSin_[0];
    normCos_[slices] = normCos_[0];
    normMidSin_[slices] = normMidSin_[0];
    normMidCos_[slices] = normMidCos_[0];
  }

  float z(int j) const { return static_cast<float>(j * height_ / stacks_); }
  float radius(int j) const {
    return static_cast<float>(base_ - deltaRadius_ * fraction(j, stacks_));
  }
  void vertex(PrimitiveEmitter& out, int i, int j) const {
    const float r = radius(j);
    out.vertex(r * sin_[i], r * cos_[i], z(j));
  }
  void smoothNormal(PrimitiveEmitter& out, int i) const {
    out.normal(normSin_[i], normCos_[i], zNormal_);
  }
  void flatNormal(PrimitiveEmitter& out, int i) const {
    out.normal(normMidSin_[i], normMidCos_[i], zNormal_);
  }
  // The normal given to the lines along the side in wireframe: GLU leaves out the z part.
  void sideLineNormal(PrimitiveEmitter& out, int i) const {
    out.normal(normSin_[i], normCos_[i], 0.0f);
  }
  void texCoord(PrimitiveEmitter& out, int i, int j) const {
    out.texCoord(oneMinusFraction(i, slices_), fraction(j, stacks_));
  }

 private:
  double base_, height_;
  int slices_, stacks_;
  float deltaRadius_;
  float zNormal_;
  std::vector<float> sin_, cos_, normSin_, normCos_, normMidSin_, normMidCos_;
};

void faceNormal(const CylinderTables& t, const QuadricStyle& style, int i, PrimitiveEmitter& out) {
  if (style.normals == kFlat) {
    t.flatNormal(out, i);
  } else if (style.normals == kSmooth) {
    t.smoothNormal(out, i);
  }
}

// One quad strip per stack; the lower ring first when seen from outside.
void filledCylinder(const CylinderTables& t, const QuadricStyle& style, int slices, int stacks,
                    PrimitiveEmitter& out) {
  const bool outside = style.orientation != kInside;
  for (int j = 0; j < stacks; ++j) {
    const int first = outside ? j : j + 1;
    const int second = outside ? j + 1 : j;
    out.begin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      faceNormal(t, style, i, out);
      if (style.textureCoords) t.texCoord(out, i, first);
      t.vertex(out, i, first);
      if (style.textureCoords) t.texCoord(out, i, second);
      t.vertex(out, i, second);
    }
    out.end();
  }
}

void pointCylinder(const CylinderTables& t, const QuadricStyle& style, int slices, int stacks,
                   PrimitiveEmitter& out) {
  out.begin(GL_POINTS);
  for (int i = 0; i < slices; ++i) {
    // Points take the smooth normal whether the style says smooth or flat.
    if (style.normals != kNoNormals) t.smoothNormal(out, i);
    for (int j = 0; j <= stacks; ++j) {
      if (style.textureCoords) t.texCoord(out, i, j);
      t.vertex(out, i, j);
    }
  }
  out.end();
}

void ringLine(const CylinderTables& t, const QuadricStyle& style, int slices, int j,
              PrimitiveEmitter& out) {
  out.begin(GL_LINE_STRIP);
  for (int i = 0; i <= slices; ++i) {
    faceNormal(t, style, i, out);
    if (style.textureCoords) t.texCoord(out, i, j);
    t.vertex(out, i, j);
  }
  out.end();
}

// GLU_LINE: every ring and every side line. GLU_SILHOUETTE: the two end rings and the side lines.
void wireCylinder(const CylinderTables& t, const QuadricStyle& style, int slices, int stacks,
                  PrimitiveEmitter& out) {
  if (style.drawStyle == kLine) {
    for (int j = 1; j < stacks; ++j) ringLine(t, style, slices, j, out);
  }
  ringLine(t, style, slices, 0, out);
  ringLine(t, style, slices, stacks, out);
  for (int i = 0; i < slices; ++i) {
    if (style.normals != kNoNormals) t.sideLineNormal(out, i);
    out.begin(GL_LINE_STRIP);
    for (int j = 0; j <= stacks; ++j) {
      if (style.textureCoords) t.texCoord(out, i, j);
      t.vertex(out, i, j);
    }
    out.end();
  }
}

}  // namespace

bool emitCylinder(const QuadricStyle& style, double baseRadius, double topRadius, double height,
                  int slices, int stacks, PrimitiveEmitter& out) {
  slices = clampDivisions(slices);
  if (slices < 2 || stacks < 1 || baseRadius < 0.0 || topRadius < 0.0 || height < 0.0) {
    return false;
  }
  const float deltaRadius = static_cast<float>(baseRadius - topRadius);
  // GLU squares the float difference in float and adds the square of the double height.
  const float deltaSquared = deltaRadius * deltaRadius;
  const float length = static_cast<float>(std::sqrt(deltaSquared + height * height));
  if (length == 0.0f) return false;
  const CylinderTables tables(baseRadius, height, slices, stacks,
                              style.orientation != kInside, deltaRadius, length);
  switch (style.drawStyle) {
    case kFill: filledCylinder(tables, style, slices, stacks, out); break;
    case kPoint: pointCylinder(tables, style, slices, stacks, out); break;
    case kLine:
    case kSilhouette: wireCylinder(tables, style, slices, stacks, out); break;
    default: break;
  }
  return true;
}

}  // namespace glass::gl::glu
