// gluSphere (GLU 1.3, section 6.7): a sphere of the given radius centred at the origin, sliced
// around the z axis like lines of longitude and stacked along it like lines of latitude.
//
// Slice i sits at the longitude theta_i = 2 pi i / slices, measured from +y towards +x, and stack
// boundary j at the colatitude phi_j = pi j / stacks from +z, so the point (i, j) is
//   (r sin phi_j sin theta_i,  r sin phi_j cos theta_i,  r cos phi_j)
// and its smooth normal is the same with r = 1 (reversed for GLU_INSIDE). Flat normals are taken
// half a slice and half a stack back, at the middle of the face they light. Texture coordinates
// run s = 1 - i / slices, t = 1 - j / stacks.
//
// Filled spheres without texture coordinates draw the two polar caps as triangle fans (the apex
// has one texture coordinate per neighbour, so textured spheres use quad strips throughout).
#include <vector>

#include "glu/quadric_tables.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl::glu {
namespace {

class SphereTables {
 public:
  SphereTables(double radius, int slices, int stacks, bool outside)
      : slices_(slices), stacks_(stacks) {
    // Longitudes. The bottom cap's normal reads entry `stacks` of this table (see bottomCap), so
    // it is filled far enough for either count.
    const int longitudeEntries = std::max(slices, stacks) + 1;
    lonSin_.resize(longitudeEntries);
    lonCos_.resize(longitudeEntries);
    lonMidSin_.resize(slices + 1);
    lonMidCos_.resize(slices + 1);
    for (int i = 0; i < longitudeEntries; ++i) {
      const SineCosine a = sineCosineOf(2.0 * kPi * i / slices);
      lonSin_[i] = a.sine;
      lonCos_[i] = a.cosine;
    }
    for (int i = 0; i < slices; ++i) {
      const SineCosine a = sineCosineOf(2.0 * kPi * (i - 0.5) / slices);
      lonMidSin_[i] = a.sine;
      lonMidCos_[i] = a.cosine;
    }
    // The seam: the last slice boundary is the first one again.
    lonSin_[slices] = lonSin_[0];
    lonCos_[slices] = lonCos_[0];
    lonMidSin_[slices] = lonMidSin_[0];
    lonMidCos_[slices] = lonMidCos_[0];

    // Colatitudes: positions scaled by the radius, normals signed by the orientation.
    const float sign = outside ? 1.0f : -1.0f;
    posSin_.resize(stacks + 1);
    posCos_.resize(stacks + 1);
    normSin_.resize(stacks + 1);
    normCos_.resize(stacks + 1);
    normMidSin_.resize(stacks + 1);
    normMidCos_.resize(stacks + 1);
    for (int j = 0; j <= stacks; ++j) {
      const double phi = static_cast<float>(kPi * j / stacks);
      normSin_[j] = sign * static_cast<float>(portable::sin(phi));
      normCos_[j] = sign * static_cast<float>(portable::cos(phi));
      posSin_[j] = static_cast<float>(radius * portable::sin(phi));
      posCos_[j] = static_cast<float>(radius * portable::cos(phi));
      const SineCosine mid = sineCosineOf(kPi * (j - 0.5) / stacks);
      normMidSin_[j] = sign * mid.sine;
      normMidCos_[j] = sign * mid.cosine;
    }
    // The poles are exact points, whatever sin(pi) rounds to.
    posSin_[0] = 0.0f;
    posSin_[stacks] = 0.0f;
  }

  void vertex(PrimitiveEmitter& out, int i, int j) const {
    out.vertex(posSin_[j] * lonSin_[i], posSin_[j] * lonCos_[i], posCos_[j]);
  }
  void smoothNormal(PrimitiveEmitter& out, int i, int j) const {
    out.normal(lonSin_[i] * normSin_[j], lonCos_[i] * normSin_[j], normCos_[j]);
  }
  // The normal of the face between slice boundaries i - 1 and i and stack boundaries j - 1, j.
  void flatNormal(PrimitiveEmitter& out, int i, int j) const {
    out.normal(lonMidSin_[i] * normMidSin_[j], lonMidCos_[i] * normMidSin_[j], normMidCos_[j]);
  }
  // Wireframe normals: along a latitude line, the face-centre longitude with the line's own
  // colatitude; along a longitude line, the reverse.
  void latitudeLineFlatNormal(PrimitiveEmitter& out, int i, int j) const {
    out.normal(lonMidSin_[i] * normSin_[j], lonMidCos_[i] * normSin_[j], normCos_[j]);
  }
  void longitudeLineFlatNormal(PrimitiveEmitter& out, int i, int j) const {
    out.normal(lonSin_[i] * normMidSin_[j], lonCos_[i] * normMidSin_[j], normMidCos_[j]);
  }
  void texCoord(PrimitiveEmitter& out, int i, int j) const {
    out.texCoord(oneMinusFraction(i, slices_), oneMinusFraction(j, stacks_));
  }

 private:
  int slices_, stacks_;
  std::vector<float> lonSin_, lonCos_, lonMidSin_, lonMidCos_;
  std::vector<float> posSin_, posCos_, normSin_, normCos_, normMidSin_, normMidCos_;
};

// The cap around the north pole (stack 0) as a fan around (0, 0, radius), wound so that its
// front faces the outside (or the inside).
void northCap(const SphereTables& t, const QuadricStyle& style, float radius, int slices,
              PrimitiveEmitter& out) {
  const bool outside = style.orientation != kInside;
  if (style.normals == kSmooth) t.smoothNormal(out, 0, 0);  // the pole's own normal
  out.begin(GL_TRIANGLE_FAN);
  out.vertex(0.0f, 0.0f, radius);
  for (int k = 0; k <= slices; ++k) {
    const int i = outside ? slices - k : k;
    if (style.normals == kSmooth) {
      t.smoothNormal(out, i, 1);
    } else if (style.normals == kFlat) {
      // Going backwards the face before vertex i lies between boundaries i and i + 1; the first
      // vertex starts no face and keeps whatever normal was current.
      if (!outside) {
        t.flatNormal(out, i, 1);
      } else if (i != slices) {
        t.flatNormal(out, i + 1, 1);
      }
    }
    t.vertex(out, i, 1);
  }
  out.end();
}

// The cap around the south pole (stack `stacks`) as a fan around (0, 0, -radius).
void southCap(const SphereTables& t, const QuadricStyle& style, float radius, int slices,
              int stacks, PrimitiveEmitter& out) {
  const bool outside = style.orientation != kInside;
  // GLU gives the pole the normal of longitude entry `stacks` (not 0); its x and y are scaled by
  // sin(pi) ~ 0, so the normal is (0, 0, -1) to within float rounding either way.
  if (style.normals == kSmooth) t.smoothNormal(out, stacks, stacks);
  out.begin(GL_TRIANGLE_FAN);
  out.vertex(0.0f, 0.0f, -radius);
  for (int k = 0; k <= slices; ++k) {
    const int i = outside ? k : slices - k;
    if (style.normals == kSmooth) {
      t.smoothNormal(out, i, stacks - 1);
    } else if (style.normals == kFlat) {
      if (outside) {
        t.flatNormal(out, i, stacks);
      } else if (i != slices) {
        t.flatNormal(out, i + 1, stacks);
      }
    }
    t.vertex(out, i, stacks - 1);
  }
  out.end();
}

// The band between stack boundaries j and j + 1 as one quad strip. Each slice boundary gives two
// vertices: the lower boundary first when seen from outside, so the quads face outwards.
void band(const SphereTables& t, const QuadricStyle& style, int slices, int j,
          PrimitiveEmitter& out) {
  const bool outside = style.orientation != kInside;
  const int first = outside ? j + 1 : j;
  const int second = outside ? j : j + 1;
  out.begin(GL_QUAD_STRIP);
  for (int i = 0; i <= slices; ++i) {
    if (style.normals == kSmooth) t.smoothNormal(out, i, first);
    if (style.textureCoords) t.texCoord(out, i, first);
    t.vertex(out, i, first);
    if (style.normals == kSmooth) {
      t.smoothNormal(out, i, second);
    } else if (style.normals == kFlat) {
      t.flatNormal(out, i, j + 1);
    }
    if (style.textureCoords) t.texCoord(out, i, second);
    t.vertex(out, i, second);
  }
  out.end();
}

void filledSphere(const SphereTables& t, const QuadricStyle& style, float radius, int slices,
                  int stacks, PrimitiveEmitter& out) {
  int firstBand = 0, lastBand = stacks;
  if (!style.textureCoords) {
    northCap(t, style, radius, slices, out);
    southCap(t, style, radius, slices, stacks, out);
    firstBand = 1;
    lastBand = stacks - 1;
  }
  for (int j = firstBand; j < lastBand; ++j) band(t, style, slices, j, out);
}

void pointSphere(const SphereTables& t, const QuadricStyle& style, int slices, int stacks,
                 PrimitiveEmitter& out) {
  out.begin(GL_POINTS);
  for (int j = 0; j <= stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      // GLU_FLAT points get the smooth normal too (a point has no face to take one from).
      if (style.normals != kNoNormals) t.smoothNormal(out, i, j);
      if (style.textureCoords) t.texCoord(out, i, j);
      t.vertex(out, i, j);
    }
  }
  out.end();
}

// GLU_LINE and GLU_SILHOUETTE draw the same net for a sphere: the inner latitude lines, then
// every longitude line from pole to pole.
void wireSphere(const SphereTables& t, const QuadricStyle& style, int slices, int stacks,
                PrimitiveEmitter& out) {
  for (int j = 1; j < stacks; ++j) {
    out.begin(GL_LINE_STRIP);
    for (int i = 0; i <= slices; ++i) {
      if (style.normals == kFlat) {
        t.latitudeLineFlatNormal(out, i, j);
      } else if (style.normals == kSmooth) {
        t.smoothNormal(out, i, j);
      }
      if (style.textureCoords) t.texCoord(out, i, j);
      t.vertex(out, i, j);
    }
    out.end();
  }
  for (int i = 0; i < slices; ++i) {
    out.begin(GL_LINE_STRIP);
    for (int j = 0; j <= stacks; ++j) {
      if (style.normals == kFlat) {
        t.longitudeLineFlatNormal(out, i, j);
      } else if (style.normals == kSmooth) {
        t.smoothNormal(out, i, j);
      }
      if (style.textureCoords) t.texCoord(out, i, j);
      t.vertex(out, i, j);
    }
    out.end();
  }
}

}  // namespace

bool emitSphere(const QuadricStyle& style, double radius, int slices, int stacks,
                PrimitiveEmitter& out) {
  slices = clampDivisions(slices);
  stacks = clampDivisions(stacks);
  if (slices < 2 || stacks < 1 || radius < 0.0) return false;
  const SphereTables tables(radius, slices, stacks, style.orientation != kInside);
  const float r = static_cast<float>(radius);
  switch (style.drawStyle) {
    case kFill: filledSphere(tables, style, r, slices, stacks, out); break;
    case kPoint: pointSphere(tables, style, slices, stacks, out); break;
    case kLine:
    case kSilhouette: wireSphere(tables, style, slices, stacks, out); break;
    default: break;
  }
  return true;
}

}  // namespace glass::gl::glu
