// Triangle setup: everything about a triangle that does not depend on the pixel, computed once.
//
// Edge functions. The vertices are snapped to 24.8 fixed point (X = round(256 x)) and put in
// counter-clockwise order, so the interior lies on the left of every edge. For the edge from
// (Xi, Yi) to (Xj, Yj):
//     E(X, Y) = A X + B Y + C,  A = Yi - Yj,  B = Xj - Xi,  C = Xi Yj - Yi Xj
// is zero on the edge and positive inside. X, Y are window coordinates times 256; the centre of
// pixel (i, j) is (256 i + 128, 256 j + 128). All of this is exact integer arithmetic in 64 bits,
// which is what makes two triangles that share an edge agree on every pixel centre along it.
//
// Putting the vertices in one orientation before building the edges means the fill does not
// depend on the order in which the caller gave them: a clockwise triangle covers exactly the
// pixels of the same triangle given counter-clockwise.
//
// A convex quadrilateral (setupQuad) has the four edge functions of its corners, made the same
// way, and the planes of its first triangle.
//
// Planes. Depth and the perspective-correct attributes are planes in window x, y fitted through
// the snapped vertex positions: window z (affine in x, y after the perspective division), and for
// each varying a, a/w and 1/w (both affine in x, y; spec 3.5.1, equation 3.8), so that at a pixel
// a = (a/w) / (1/w).
#include <algorithm>
#include <cmath>

#include "glass/raster/triangle.h"
#include "subpixel.h"

namespace glass::raster {
namespace {

// Coefficients of the plane v(x, y) = v0 + dvdx x + dvdy y through three points.
struct Plane {
  double v0, dvdx, dvdy;
};

Plane fitPlane(const double x[3], const double y[3], double v0, double v1, double v2,
               double area) {
  const double d1 = v1 - v0, d2 = v2 - v0;
  Plane p;
  p.dvdx = (d1 * (y[2] - y[0]) - d2 * (y[1] - y[0])) / area;
  p.dvdy = (d2 * (x[1] - x[0]) - d1 * (x[2] - x[0])) / area;
  p.v0 = v0 - p.dvdx * x[0] - p.dvdy * y[0];
  return p;
}

// A triangle's vertices snapped to the subpixel grid and put in counter-clockwise order: what
// both steps of setup start from.
struct SnappedTriangle {
  int64_t X[3], Y[3];
  const WindowVertex* v[3];  // the vertices in that order
  bool reversed;             // given clockwise
};

// False for a position that cannot be rasterized or a triangle of no area.
bool snapTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, SnappedTriangle& t) {
  t.v[0] = &a;
  t.v[1] = &b;
  t.v[2] = &c;
  for (const WindowVertex* p : t.v)
    if (!isRasterizableCoordinate(p->x) || !isRasterizableCoordinate(p->y)) return false;
  for (int i = 0; i < 3; ++i) {
    t.X[i] = snapToSubpixel(t.v[i]->x);
    t.Y[i] = snapToSubpixel(t.v[i]->y);
  }
  const int64_t area = (t.X[1] - t.X[0]) * (t.Y[2] - t.Y[0]) - (t.X[2] - t.X[0]) * (t.Y[1] - t.Y[0]);
  if (area == 0) return false;
  t.reversed = area < 0;
  if (t.reversed) {  // clockwise: walk it the other way round
    std::swap(t.X[1], t.X[2]);
    std::swap(t.Y[1], t.Y[2]);
    std::swap(t.v[1], t.v[2]);
  }
  return true;
}

// The box, clipped to the bounds, and the edge functions of the counter-clockwise polygon X, Y
// of n corners (3 or 4): integer arithmetic only. False when the box is empty.
template <int n>
bool setEdges(const int64_t (&X)[n], const int64_t (&Y)[n], const PixelRect& bounds, TriangleSetup& setup) {
  static_assert(n <= TriangleSetup::kMaxEdges);
  // Pixels whose centre 256 i + 128 lies within [min X, max X] (and the same in y); arithmetic
  // shifts are floor divisions, also for negative coordinates.
  int64_t minX = X[0], maxX = X[0], minY = Y[0], maxY = Y[0];
  for (int i = 1; i < n; ++i) {
    minX = std::min(minX, X[i]);
    maxX = std::max(maxX, X[i]);
    minY = std::min(minY, Y[i]);
    maxY = std::max(maxY, Y[i]);
  }
  PixelRect box;
  box.x0 = std::max<int64_t>(bounds.x0, (minX - kSubpixelHalf + kSubpixelOne - 1) >> kSubpixelBits);
  box.y0 = std::max<int64_t>(bounds.y0, (minY - kSubpixelHalf + kSubpixelOne - 1) >> kSubpixelBits);
  box.x1 = std::min<int64_t>(bounds.x1, ((maxX - kSubpixelHalf) >> kSubpixelBits) + 1);
  box.y1 = std::min<int64_t>(bounds.y1, ((maxY - kSubpixelHalf) >> kSubpixelBits) + 1);
  if (box.empty()) return false;
  setup.box = box;

  setup.edgeCount = n;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    setup.edgeA[i] = Y[i] - Y[j];
    setup.edgeB[i] = X[j] - X[i];
    setup.edgeC[i] = X[i] * Y[j] - Y[i] * X[j];
  }
  return true;
}

bool setEdges(const SnappedTriangle& t, const PixelRect& bounds, TriangleSetup& setup) {
  return setEdges(t.X, t.Y, bounds, setup);
}

// A quadrilateral's corners snapped to the subpixel grid and put in counter-clockwise order;
// false unless they make a strictly convex quadrilateral (every corner turning the same way,
// none straight), which also makes both its triangles non-degenerate.
struct SnappedQuad {
  int64_t X[4], Y[4];
};

bool snapQuad(const WindowVertex* const (&v)[4], SnappedQuad& q) {
  for (const WindowVertex* p : v)
    if (!isRasterizableCoordinate(p->x) || !isRasterizableCoordinate(p->y)) return false;
  for (int i = 0; i < 4; ++i) {
    q.X[i] = snapToSubpixel(v[i]->x);
    q.Y[i] = snapToSubpixel(v[i]->y);
  }
  // Coordinates below 2^28 in magnitude: differences below 2^29, products below 2^58.
  int positive = 0, negative = 0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4, k = (i + 2) % 4;
    const int64_t turn = (q.X[j] - q.X[i]) * (q.Y[k] - q.Y[j]) - (q.Y[j] - q.Y[i]) * (q.X[k] - q.X[j]);
    positive += turn > 0;
    negative += turn < 0;
  }
  if (negative == 4) {  // clockwise: go round the other way
    std::swap(q.X[1], q.X[3]);
    std::swap(q.Y[1], q.Y[3]);
    return true;
  }
  return positive == 4;
}

// The depth and attribute planes (the divisions of setup), the signed area, and the settings the
// rasterizer passes on.
[[gnu::always_inline]] inline void setPlanes(const SnappedTriangle& t, const TriangleSettings& settings,
                                             TriangleSetup& setup) {
  const WindowVertex* const* v = t.v;
  // Planes in pixel units, through the snapped positions (exact in double).
  double x[3], y[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = static_cast<double>(t.X[i]) / double(kSubpixelOne);
    y[i] = static_cast<double>(t.Y[i]) / double(kSubpixelOne);
  }
  const double planeArea = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  setup.signedArea = t.reversed ? -planeArea : planeArea;

  const Plane z = fitPlane(x, y, v[0]->z, v[1]->z, v[2]->z, planeArea);
  setup.z0 = z.v0 + settings.depthBias;
  setup.zdx = z.dvdx;
  setup.zdy = z.dvdy;

  const int varyingCount = std::clamp(settings.varyingCount, 0, kMaxVaryings);
  // q = 1/w when perspective-correct; q = 1 makes every varying affine in screen space.
  double q[3];
  for (int i = 0; i < 3; ++i) q[i] = settings.perspectiveCorrect ? double(v[i]->invW) : 1.0;
  AttributePlanes& planes = setup.planes;
  const Plane invW = fitPlane(x, y, q[0], q[1], q[2], planeArea);
  planes.invW0 = invW.v0;
  planes.invWdx = invW.dvdx;
  planes.invWdy = invW.dvdy;
  for (int k = 0; k < varyingCount; ++k) {
    const Plane p = fitPlane(x, y, v[0]->varyings[k] * q[0], v[1]->varyings[k] * q[1],
                             v[2]->varyings[k] * q[2], planeArea);
    planes.a0[k] = p.v0;
    planes.dx[k] = p.dvdx;
    planes.dy[k] = p.dvdy;
  }
  setup.varyingCount = varyingCount;
  setup.perspectiveCorrect = settings.perspectiveCorrect;
  setup.frontFacing = settings.frontFacing;
  setup.earlyDepth = settings.earlyDepth;
  setup.depthUsed = settings.depthUsed;
  setup.payload = settings.payload;
}

}  // namespace

double windowSignedArea(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c) {
  return (static_cast<double>(b.x) - a.x) * (static_cast<double>(c.y) - a.y) -
         (static_cast<double>(c.x) - a.x) * (static_cast<double>(b.y) - a.y);
}

bool setupTriangleEdges(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                        const PixelRect& bounds, TriangleSetup& setup) {
  SnappedTriangle t;
  return snapTriangle(a, b, c, t) && setEdges(t, bounds, setup);
}

bool setupTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                   const TriangleSettings& settings, TriangleSetup& setup) {
  SnappedTriangle t;
  if (!snapTriangle(a, b, c, t) || !setEdges(t, settings.bounds, setup)) return false;
  setPlanes(t, settings, setup);
  return true;
}

bool quadIsConvex(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const WindowVertex& v3) {
  SnappedQuad q;
  return snapQuad({&v0, &v1, &v2, &v3}, q);
}

bool setupQuadEdges(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                    const WindowVertex& v3, const PixelRect& bounds, TriangleSetup& setup) {
  SnappedQuad q;
  return snapQuad({&v0, &v1, &v2, &v3}, q) && setEdges(q.X, q.Y, bounds, setup);
}

bool setupQuad(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const WindowVertex& v3,
               const TriangleSettings& settings, TriangleSetup& setup) {
  SnappedTriangle first;
  if (!setupQuadEdges(v0, v1, v2, v3, settings.bounds, setup) || !snapTriangle(v0, v1, v2, first)) return false;
  setPlanes(first, settings, setup);
  return true;
}

}  // namespace glass::raster
