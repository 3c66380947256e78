// Clipping in homogeneous clip space (OpenGL 1.5 spec, section 2.12).
//
// Every clip plane is a linear function of the vertex, d(v) >= 0 meaning inside:
//   frustum planes  w + x, w - x, w + y, w - y, w + z, w - z   (so -w <= x, y, z <= w)
//   user plane i    userClipDistance[i]   (p_i . v_eye, carried by the vertex)
// Because each d is linear in the homogeneous coordinates, the point where an edge crosses a plane
// is at t = d_in / (d_in - d_out) along it, and every attribute is interpolated with the same t
// (the specification's "the values of t ... used to interpolate the attributes").
//
// Working in clip space before the division by w is what makes primitives that cross w = 0 come
// out right: a point with w <= 0 fails at least one of w + x >= 0 and w - x >= 0 (unless x = w = 0),
// so the part of a triangle behind the eye is cut off before anything is divided by w.
//
// Non-finite coordinates (spec 2.1.1: the results are undefined, but the GL must not be
// interrupted) make a vertex outside every plane and flag it kNotFinite: a point there is not
// drawn, and neither is a line or polygon with such a vertex, since where it crosses a plane
// cannot be computed (infinity minus infinity is NaN).
#include "glass/raster/clip.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace glass::raster {
namespace {

constexpr int kFrustumPlanes = 6;
constexpr int kAllPlanes = kFrustumPlanes + kMaxUserClipPlanes;

// Signed distance of a vertex to plane `plane` (0-5 frustum, 6-11 user), inside when >= 0.
inline float planeDistance(const ClipVertex& v, int plane) {
  const float w = v.clip[3];
  switch (plane) {
    case 0: return w + v.clip[0];
    case 1: return w - v.clip[0];
    case 2: return w + v.clip[1];
    case 3: return w - v.clip[1];
    case 4: return w + v.clip[2];
    case 5: return w - v.clip[2];
    default: return v.userClipDistance[plane - kFrustumPlanes];
  }
}

inline unsigned enabledPlaneMask(const ClipSettings& settings) {
  return 0x3Fu | ((settings.userPlaneMask & ((1u << kMaxUserClipPlanes) - 1u)) << kFrustumPlanes);
}

// from + t * (to - from), every component, computed in double and rounded once to float.
void interpolate(const ClipVertex& from, const ClipVertex& to, double t, int varyingCount,
                 ClipVertex& out) {
  auto lerp = [t](float a, float b) {
    return static_cast<float>(static_cast<double>(a) + t * (static_cast<double>(b) - a));
  };
  for (int i = 0; i < 4; ++i) out.clip[i] = lerp(from.clip[i], to.clip[i]);
  for (int i = 0; i < kMaxUserClipPlanes; ++i)
    out.userClipDistance[i] = lerp(from.userClipDistance[i], to.userClipDistance[i]);
  for (int i = 0; i < varyingCount; ++i) out.varyings[i] = lerp(from.varyings[i], to.varyings[i]);
}

// The point where the edge (inside, outside) crosses `plane`. The parameter is always measured
// from the inside vertex, so an edge shared by two polygons (walked in opposite directions) is
// cut at bit-identical points and the clipped polygons still share their new edge exactly.
void intersect(const ClipVertex& inside, float dInside, const ClipVertex& outside, float dOutside,
               int plane, int varyingCount, ClipVertex& out) {
  const double t = static_cast<double>(dInside) / (static_cast<double>(dInside) - dOutside);
  interpolate(inside, outside, t, varyingCount, out);
  // Put the new vertex exactly on a frustum plane, so that x/w (or y/w, z/w) is exactly +-1.
  if (plane < kFrustumPlanes) {
    const int axis = plane / 2;
    out.clip[axis] = (plane % 2 == 0) ? -out.clip[3] : out.clip[3];
  } else {
    out.userClipDistance[plane - kFrustumPlanes] = 0.0f;
  }
}

// One Sutherland-Hodgman pass: the part of polygon `in` (n vertices) on the inside of `plane`.
// A convex polygon gains at most one vertex per pass; `capacity` only guards memory against a
// polygon made slightly non-convex by rounding, whose extra vertices are then dropped.
int clipAgainstPlane(const ClipVertex* in, int n, int plane, int varyingCount, ClipVertex* out,
                     int capacity) {
  int count = 0;
  const ClipVertex* previous = &in[n - 1];
  float dPrevious = planeDistance(*previous, plane);
  for (int i = 0; i < n; ++i) {
    const ClipVertex& current = in[i];
    const float dCurrent = planeDistance(current, plane);
    const bool previousInside = dPrevious >= 0.0f;
    const bool currentInside = dCurrent >= 0.0f;
    if (previousInside != currentInside && count < capacity) {
      if (previousInside)
        intersect(*previous, dPrevious, current, dCurrent, plane, varyingCount, out[count++]);
      else
        intersect(current, dCurrent, *previous, dPrevious, plane, varyingCount, out[count++]);
    }
    if (currentInside && count < capacity) out[count++] = current;
    previous = &current;
    dPrevious = dCurrent;
  }
  return count;
}

// The bits of the six frustum planes a vertex with finite clip coordinates lies outside of
// (planeDistance's order: -w <= x, x <= w, then y, then z), without branches.
inline unsigned frustumBits(float x, float y, float z, float w) {
  return static_cast<unsigned>(!(w + x >= 0.0f)) | static_cast<unsigned>(!(w - x >= 0.0f)) << 1 |
         static_cast<unsigned>(!(w + y >= 0.0f)) << 2 | static_cast<unsigned>(!(w - y >= 0.0f)) << 3 |
         static_cast<unsigned>(!(w + z >= 0.0f)) << 4 | static_cast<unsigned>(!(w - z >= 0.0f)) << 5;
}

// std::isfinite of all four, as comparisons (NaN compares false).
inline bool allFinite(float x, float y, float z, float w) {
  constexpr float kLargest = std::numeric_limits<float>::max();
  return (std::fabs(x) <= kLargest) & (std::fabs(y) <= kLargest) & (std::fabs(z) <= kLargest) &
         (std::fabs(w) <= kLargest);
}

}  // namespace

unsigned outcode(const ClipVertex& v, const ClipSettings& settings) {
  const unsigned enabled = enabledPlaneMask(settings);
  if (!allFinite(v.clip[0], v.clip[1], v.clip[2], v.clip[3])) return enabled | kNotFinite;
  // The six frustum planes, always enabled; then the enabled user planes.
  unsigned code = frustumBits(v.clip[0], v.clip[1], v.clip[2], v.clip[3]);
  for (unsigned user = enabled >> kFrustumPlanes; user != 0; user &= user - 1) {
    const int plane = kFrustumPlanes + std::countr_zero(user);
    if (!(planeDistance(v, plane) >= 0.0f)) code |= 1u << plane;
  }
  return code;
}

void frustumOutcodes(const float* x, const float* y, const float* z, const float* w, int count,
                     unsigned* codes) {
  const unsigned notFinite = enabledPlaneMask(ClipSettings{}) | kNotFinite;
  for (int i = 0; i < count; ++i) {
    // Without a branch: notFinite holds every frustum bit.
    const unsigned finite = allFinite(x[i], y[i], z[i], w[i]);
    codes[i] = frustumBits(x[i], y[i], z[i], w[i]) | (notFinite & (finite - 1u));
  }
}

bool pointInside(const ClipVertex& v, const ClipSettings& settings) {
  return outcode(v, settings) == 0;
}

int clipPolygon(const ClipVertex* in, int n, const ClipSettings& settings, ClipVertex* out) {
  if (n < 3) return 0;
  unsigned any = 0, all = ~0u;
  for (int i = 0; i < n; ++i) {
    const unsigned code = outcode(in[i], settings);
    any |= code;
    all &= code;
  }
  if (all != 0 || (any & kNotFinite)) return 0;  // every vertex outside one plane, or one unknown
  if (any == 0) {          // every vertex inside every plane
    std::copy(in, in + n, out);
    return n;
  }

  // Each pass adds at most one vertex to a convex polygon, so n + 12 vertices always suffice.
  // Passes alternate between `out` and a scratch buffer; the scratch lives on the stack for the
  // polygons the pipeline sends (triangles, quads) and on the heap only for very large polygons.
  constexpr int kStackScratch = 64;
  const int capacity = n + kAllPlanes;
  ClipVertex stackScratch[kStackScratch];
  std::vector<ClipVertex> heapScratch;
  ClipVertex* scratch = stackScratch;
  if (capacity > kStackScratch) {
    heapScratch.resize(static_cast<size_t>(capacity));
    scratch = heapScratch.data();
  }

  // The number of passes decides which buffer holds the result; start in the buffer that makes the
  // last pass write to `out`.
  int passes = 0;
  for (int plane = 0; plane < kAllPlanes; ++plane) passes += (any >> plane) & 1u;
  ClipVertex* buffers[2] = {out, scratch};
  int target = (passes % 2 == 0) ? 1 : 0;  // first pass writes here; after `passes` flips: out

  const ClipVertex* source = in;
  int count = n;
  for (int plane = 0; plane < kAllPlanes && count > 0; ++plane) {
    if (!((any >> plane) & 1u)) continue;
    count = clipAgainstPlane(source, count, plane, settings.varyingCount, buffers[target], capacity);
    source = buffers[target];
    target ^= 1;
  }
  if (count < 3) return 0;
  if (source != out) std::copy(source, source + count, out);  // when a pass emptied the polygon early
  return count;
}

bool clipLine(ClipVertex& a, ClipVertex& b, const ClipSettings& settings) {
  const unsigned codeA = outcode(a, settings), codeB = outcode(b, settings);
  if ((codeA & codeB) || ((codeA | codeB) & kNotFinite)) return false;
  if ((codeA | codeB) == 0) return true;

  // Liang-Barsky: the segment a + t (b - a), t in [tEnter, tLeave], shrunk plane by plane.
  double tEnter = 0.0, tLeave = 1.0;
  const unsigned crossed = codeA | codeB;
  for (int plane = 0; plane < kAllPlanes; ++plane) {
    if (!((crossed >> plane) & 1u)) continue;
    const double da = planeDistance(a, plane), db = planeDistance(b, plane);
    const double t = da / (da - db);
    if (da < 0.0) tEnter = std::max(tEnter, t);
    else tLeave = std::min(tLeave, t);
    if (tEnter > tLeave) return false;
  }
  const ClipVertex originalA = a, originalB = b;
  if (codeA) interpolate(originalA, originalB, tEnter, settings.varyingCount, a);
  if (codeB) interpolate(originalA, originalB, tLeave, settings.varyingCount, b);
  return true;
}

}  // namespace glass::raster
