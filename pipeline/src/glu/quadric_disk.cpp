// gluDisk and gluPartialDisk (GLU 1.3, sections 6.9 and 6.10): a flat annulus in the plane z = 0
// between radii inner and outer, optionally only the sector from startAngle sweeping sweepAngle
// degrees (measured clockwise from +y, as GLU does: the point at angle a is (r sin a, r cos a)).
//
// Loop boundary j sits at radius r_j = outer - (outer - inner) j / loops. The normal is +z
// (GLU_OUTSIDE) or -z, given once. Texture coordinates map the disk of radius `outer` onto the
// unit square: (0.5 + r sin a / (2 outer), 0.5 + r cos a / (2 outer)).
#include <cmath>
#include <vector>

#include "glu/quadric_tables.h"

namespace glass::gl::glu {
namespace {

class DiskTables {
 public:
  DiskTables(double inner, double outer, int slices, int loops, double startAngle,
             double sweepAngle)
      : inner_(inner), outer_(outer), loops_(loops) {
    deltaRadius_ = static_cast<float>(outer - inner);
    sin_.resize(slices + 1);
    cos_.resize(slices + 1);
    const float offset = static_cast<float>(startAngle / 180.0 * kPi);
    for (int i = 0; i <= slices; ++i) {
      const SineCosine a = sineCosineOf(offset + ((kPi * sweepAngle) / 180.0) * i / slices);
      sin_[i] = a.sine;
      cos_[i] = a.cosine;
    }
    if (sweepAngle == 360.0) {  // a whole disk closes exactly
      sin_[slices] = sin_[0];
      cos_[slices] = cos_[0];
    }
  }

  float radius(int j) const {
    return static_cast<float>(outer_ - deltaRadius_ * fraction(j, loops_));
  }
  // The texture radius of loop j: r_j / outer / 2.
  float texRadius(int j) const { return static_cast<float>(radius(j) / outer_ / 2); }

  void vertex(PrimitiveEmitter& out, int i, int j) const {
    const float r = radius(j);
    out.vertex(r * sin_[i], r * cos_[i], 0.0f);
  }
  void texCoord(PrimitiveEmitter& out, int i, int j) const {
    const float tr = texRadius(j);
    out.texCoord(static_cast<float>(tr * sin_[i] + 0.5), static_cast<float>(tr * cos_[i] + 0.5));
  }
  // A disk with inner == outer degenerates to a circle of radius inner; GLU then maps the
  // texture as if that circle were the rim.
  void circleVertex(PrimitiveEmitter& out, int i) const {
    out.vertex(static_cast<float>(inner_ * sin_[i]), static_cast<float>(inner_ * cos_[i]), 0.0f);
  }
  void circleTexCoord(PrimitiveEmitter& out, int i) const {
    out.texCoord(static_cast<float>(sin_[i] / 2 + 0.5), static_cast<float>(cos_[i] / 2 + 0.5));
  }

 private:
  double inner_, outer_;
  int loops_;
  float deltaRadius_;
  std::vector<float> sin_, cos_;
};

void filledDisk(const DiskTables& t, const QuadricStyle& style, double inner, int slices,
                int loops, PrimitiveEmitter& out) {
  const bool outside = style.orientation != kInside;
  int rings = loops;
  if (inner == 0.0) {
    // The innermost loop is a fan around the centre, wound to face +z from outside.
    rings = loops - 1;
    out.begin(GL_TRIANGLE_FAN);
    if (style.textureCoords) out.texCoord(0.5f, 0.5f);
    out.vertex(0.0f, 0.0f, 0.0f);
    for (int k = 0; k <= slices; ++k) {
      const int i = outside ? slices - k : k;
      if (style.textureCoords) t.texCoord(out, i, loops - 1);
      t.vertex(out, i, loops - 1);
    }
    out.end();
  }
  for (int j = 0; j < rings; ++j) {
    const int first = outside ? j : j + 1;
    const int second = outside ? j + 1 : j;
    out.begin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      if (style.textureCoords) t.texCoord(out, i, first);
      t.vertex(out, i, first);
      if (style.textureCoords) t.texCoord(out, i, second);
      t.vertex(out, i, second);
    }
    out.end();
  }
}

void pointDisk(const DiskTables& t, const QuadricStyle& style, int spokes, int loops,
               PrimitiveEmitter& out) {
  out.begin(GL_POINTS);
  for (int i = 0; i < spokes; ++i) {
    for (int j = 0; j <= loops; ++j) {
      if (style.textureCoords) t.texCoord(out, i, j);
      t.vertex(out, i, j);
    }
  }
  out.end();
}

void loopLine(const DiskTables& t, const QuadricStyle& style, int slices, int j,
              PrimitiveEmitter& out) {
  out.begin(GL_LINE_STRIP);
  for (int i = 0; i <= slices; ++i) {
    if (style.textureCoords) t.texCoord(out, i, j);
    t.vertex(out, i, j);
  }
  out.end();
}

void spokeLine(const DiskTables& t, const QuadricStyle& style, int loops, int i,
               PrimitiveEmitter& out) {
  out.begin(GL_LINE_STRIP);
  for (int j = 0; j <= loops; ++j) {
    if (style.textureCoords) t.texCoord(out, i, j);
    t.vertex(out, i, j);
  }
  out.end();
}

// GLU_LINE: every loop and every spoke.
void lineDisk(const DiskTables& t, const QuadricStyle& style, double inner, double outer,
              int slices, int spokes, int loops, PrimitiveEmitter& out) {
  if (inner == outer) {
    out.begin(GL_LINE_STRIP);
    for (int i = 0; i <= slices; ++i) {
      if (style.textureCoords) t.circleTexCoord(out, i);
      t.circleVertex(out, i);
    }
    out.end();
    return;
  }
  for (int j = 0; j <= loops; ++j) loopLine(t, style, slices, j, out);
  for (int i = 0; i < spokes; ++i) spokeLine(t, style, loops, i, out);
}

// GLU_SILHOUETTE: the outline only; the two straight edges of a partial disk, then the outer
// and inner arcs.
void silhouetteDisk(const DiskTables& t, const QuadricStyle& style, double inner, double outer,
                    int slices, int loops, double sweepAngle, PrimitiveEmitter& out) {
  if (sweepAngle < 360.0) {
    spokeLine(t, style, loops, 0, out);
    spokeLine(t, style, loops, slices, out);
  }
  loopLine(t, style, slices, 0, out);
  if (inner != outer) loopLine(t, style, slices, loops, out);
}

}  // namespace

bool emitPartialDisk(const QuadricStyle& style, double innerRadius, double outerRadius,
                     int slices, int loops, double startAngle, double sweepAngle,
                     PrimitiveEmitter& out) {
  slices = clampDivisions(slices);
  if (slices < 2 || loops < 1 || outerRadius <= 0.0 || innerRadius < 0.0 ||
      innerRadius > outerRadius) {
    return false;
  }
  // Sweeps beyond a full turn draw the whole disk (GLU also turns sweeps below -360 into +360);
  // a negative sweep runs the same sector from its other end.
  if (sweepAngle < -360.0 || sweepAngle > 360.0) sweepAngle = 360.0;
  if (sweepAngle < 0.0) {
    startAngle += sweepAngle;
    sweepAngle = -sweepAngle;
  }
  // A partial disk has one more spoke than slices; a whole one closes on its first spoke.
  const int spokes = sweepAngle == 360.0 ? slices : slices + 1;
  const DiskTables tables(innerRadius, outerRadius, slices, loops, startAngle, sweepAngle);

  if (style.normals != kNoNormals) {
    out.normal(0.0f, 0.0f, style.orientation != kInside ? 1.0f : -1.0f);
  }
  switch (style.drawStyle) {
    case kFill: filledDisk(tables, style, innerRadius, slices, loops, out); break;
    case kPoint: pointDisk(tables, style, spokes, loops, out); break;
    case kLine:
      lineDisk(tables, style, innerRadius, outerRadius, slices, spokes, loops, out);
      break;
    case kSilhouette:
      silhouetteDisk(tables, style, innerRadius, outerRadius, slices, loops, sweepAngle, out);
      break;
    default: break;
  }
  return true;
}

}  // namespace glass::gl::glu
