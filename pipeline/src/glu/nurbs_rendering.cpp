// Drawing NURBS curves and surfaces (GLU 1.3 specification, chapter 7), at gluEndCurve and
// gluEndSurface.
//
// Every map (the geometry and any normal, colour or texture coordinate maps) is split into Bezier
// pieces at the union of all maps' knots (glass/geometry/nurbs.h), so that the maps' pieces
// cover the same parameter rectangles. Each piece is sampled on a uniform grid whose step comes
// from GLU's sampling method (nurbs_sampling.h); the smallest step of all pieces is used for the
// whole surface, so that neighbouring pieces meet at the same points and leave no cracks.
//
// In GLU_NURBS_RENDERER mode the pieces are drawn as SGI's GLU draws them, through the GL
// evaluators: glMap2f for every map of the piece (inside glPushAttrib(GL_EVAL_BIT)), then
// glMapGrid2f and glEvalMesh2, so positions, normals (GL_AUTO_NORMAL, if the program enabled it)
// and colours are computed by the GL. Trimmed surfaces: each grid cell that a trimming loop
// crosses is cut to the trimmed region with the polygon tessellator (the region kept lies to the
// left of the loops: counter-clockwise outer loops, clockwise holes) and its triangles are drawn
// with glEvalCoord2f. In GLU_NURBS_TESSELLATOR mode the same primitives (quad strips for whole
// grids, triangles, lines) are evaluated here and reported through the GLU_NURBS_* callbacks
// instead.
//
// GLU_OUTLINE_POLYGON draws the tessellation's edges, GLU_OUTLINE_PATCH the boundaries of the
// pieces, or of the trimming loops of a trimmed surface.
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "glass/geometry/nurbs.h"
#include "glass/geometry/polygon_tessellation.h"
#include "glu/nurbs_object.h"
#include "glu/nurbs_sampling.h"

namespace glass::gl::glu {

namespace {

using geometry::BezierCurvePiece;
using geometry::BezierSurfacePiece;
using geometry::PlanarPoint;
using Map = GLUnurbs::Map;

bool isGeometry(GLenum type) {
  return type == GL_MAP1_VERTEX_3 || type == GL_MAP1_VERTEX_4 || type == GL_MAP2_VERTEX_3 ||
         type == GL_MAP2_VERTEX_4;
}

// A Bezier polynomial of `count` points of `dimension` coordinates (`stride` numbers apart) at
// t in [0, 1] by de Casteljau's construction, with its derivative in t.
void evaluateBezier(const double* points, int count, int stride, int dimension, double t,
                    double* value, double* derivative) {
  std::vector<double> work(static_cast<size_t>(count) * dimension);
  for (int i = 0; i < count; ++i) {
    for (int c = 0; c < dimension; ++c) work[i * dimension + c] = points[i * stride + c];
  }
  for (int level = count - 1; level >= 1; --level) {
    if (level == 1 && derivative) {
      for (int c = 0; c < dimension; ++c) {
        derivative[c] = (count - 1) * (work[dimension + c] - work[c]);
      }
    }
    for (int i = 0; i < level; ++i) {
      for (int c = 0; c < dimension; ++c) {
        work[i * dimension + c] =
            (1.0 - t) * work[i * dimension + c] + t * work[(i + 1) * dimension + c];
      }
    }
  }
  if (count == 1 && derivative) std::fill_n(derivative, dimension, 0.0);
  std::copy_n(work.data(), dimension, value);
}

// A surface piece at (s, t) in [0, 1]^2: value and partial derivatives.
void evaluatePatch(const std::vector<double>& points, int uOrder, int vOrder, int dimension,
                   double s, double t, double* value, double* du, double* dv) {
  std::vector<double> rows(static_cast<size_t>(uOrder) * dimension);
  std::vector<double> rowDerivatives(static_cast<size_t>(uOrder) * dimension);
  for (int i = 0; i < uOrder; ++i) {
    evaluateBezier(&points[static_cast<size_t>(i) * vOrder * dimension], vOrder, dimension,
                   dimension, t, &rows[i * dimension], &rowDerivatives[i * dimension]);
  }
  evaluateBezier(rows.data(), uOrder, dimension, dimension, s, value, du);
  std::vector<double> unused(dimension);
  evaluateBezier(rowDerivatives.data(), uOrder, dimension, dimension, s, dv, unused.data());
}

// Reports values through a callback's _DATA form when set, else its plain form.
void reportValue(void (*plain)(GLfloat*), void (*withData)(GLfloat*, void*), void* data,
                 GLfloat* values) {
  if (withData) {
    withData(values, data);
  } else if (plain) {
    plain(values);
  }
}

// One map's piece over the piece rectangle being drawn.
struct PieceMap {
  const Map* map;
  const BezierSurfacePiece* piece;
};

// A point of the parameter domain with the values the callbacks report there.
struct DomainPoint {
  double u, v;
};

// Where a surface's triangles and lines go: the GL (renderer mode) or the callbacks.
class SurfaceOutput {
 public:
  SurfaceOutput(GLUnurbs& nurb, bool renderer) : nurb_(nurb), renderer_(renderer) {}

  void bind(const std::vector<PieceMap>& maps) {
    maps_ = &maps;
    if (!renderer_) return;
    for (const PieceMap& m : maps) {
      const Map& map = *m.map;
      std::vector<float> points(m.piece->points.begin(), m.piece->points.end());
      glMap2f(map.type, static_cast<float>(m.piece->u0), static_cast<float>(m.piece->u1),
              map.vOrder * map.dimension, map.uOrder, static_cast<float>(m.piece->v0),
              static_cast<float>(m.piece->v1), map.dimension, map.vOrder, points.data());
      glEnable(map.type);
    }
  }

  // The whole piece as an nu x nv grid.
  void grid(const BezierSurfacePiece& p, int nu, int nv) {
    if (renderer_ && nurb_.displayMode != GLU_OUTLINE_PATCH) {
      glMapGrid2f(nu, static_cast<float>(p.u0), static_cast<float>(p.u1), nv,
                  static_cast<float>(p.v0), static_cast<float>(p.v1));
      glEvalMesh2(GL_FILL, 0, nu, 0, nv);
      return;
    }
    if (nurb_.displayMode == GLU_OUTLINE_PATCH) {
      outlineRectangle(p, nu, nv);
      return;
    }
    if (nurb_.displayMode == GLU_FILL) {
      quadStrips(p, nu, nv);
      return;
    }
    std::vector<DomainPoint> triangles;
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nv; ++j) cellTriangles(p, nu, nv, i, j, triangles);
    }
    emitTriangles(triangles);
  }

  // Triangles given by their corners in the domain, counter-clockwise.
  void emitTriangles(const std::vector<DomainPoint>& corners) {
    if (corners.empty()) return;
    const bool outline = nurb_.displayMode == GLU_OUTLINE_POLYGON;
    if (renderer_) {
      glBegin(GL_TRIANGLES);
      for (const DomainPoint& d : corners) {
        glEvalCoord2f(static_cast<float>(d.u), static_cast<float>(d.v));
      }
      glEnd();
      return;
    }
    if (outline) {
      for (size_t k = 0; k < corners.size(); k += 3) {
        callBegin(GL_LINE_LOOP);
        for (size_t c = 0; c < 3; ++c) callVertex(corners[k + c]);
        callEnd();
      }
      return;
    }
    callBegin(GL_TRIANGLES);
    for (const DomainPoint& d : corners) callVertex(d);
    callEnd();
  }

  // A polyline in the domain, drawn on the surface.
  void emitLineStrip(const std::vector<DomainPoint>& points) {
    if (points.size() < 2) return;
    if (renderer_) {
      glBegin(GL_LINE_STRIP);
      for (const DomainPoint& d : points) {
        glEvalCoord2f(static_cast<float>(d.u), static_cast<float>(d.v));
      }
      glEnd();
      return;
    }
    callBegin(GL_LINE_STRIP);
    for (const DomainPoint& d : points) callVertex(d);
    callEnd();
  }

  static void cellTriangles(const BezierSurfacePiece& p, int nu, int nv, int i, int j,
                            std::vector<DomainPoint>& out) {
    const double u0 = p.u0 + (p.u1 - p.u0) * i / nu, u1 = p.u0 + (p.u1 - p.u0) * (i + 1) / nu;
    const double v0 = p.v0 + (p.v1 - p.v0) * j / nv, v1 = p.v0 + (p.v1 - p.v0) * (j + 1) / nv;
    out.insert(out.end(), {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v0}, {u1, v1}, {u0, v1}});
  }

 private:
  // The grid as the renderer mode's glEvalMesh2(GL_FILL) draws it (spec 5.1): one quad strip for
  // every row of cells, its vertices alternating between the row's lower and upper edges. SGI's
  // GLU reports quad strips too, so a program that draws what the callbacks report gets the same
  // quadrilaterals (and the same edges in glPolygonMode GL_LINE) as the renderer mode draws.
  void quadStrips(const BezierSurfacePiece& p, int nu, int nv) {
    for (int j = 0; j < nv; ++j) {
      const double v0 = p.v0 + (p.v1 - p.v0) * j / nv, v1 = p.v0 + (p.v1 - p.v0) * (j + 1) / nv;
      callBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= nu; ++i) {
        const double u = p.u0 + (p.u1 - p.u0) * i / nu;
        callVertex({u, v0});
        callVertex({u, v1});
      }
      callEnd();
    }
  }

  // The piece's four sides.
  void outlineRectangle(const BezierSurfacePiece& p, int nu, int nv) {
    if (renderer_) {
      glMapGrid2f(nu, static_cast<float>(p.u0), static_cast<float>(p.u1), nv,
                  static_cast<float>(p.v0), static_cast<float>(p.v1));
      glEvalMesh2(GL_LINE, 0, nu, 0, 0);
      glEvalMesh2(GL_LINE, 0, nu, nv, nv);
      glEvalMesh2(GL_LINE, 0, 0, 0, nv);
      glEvalMesh2(GL_LINE, nu, nu, 0, nv);
      return;
    }
    auto side = [&](double ua, double va, double ub, double vb, int n) {
      std::vector<DomainPoint> line;
      for (int k = 0; k <= n; ++k) line.push_back({ua + (ub - ua) * k / n, va + (vb - va) * k / n});
      emitLineStrip(line);
    };
    side(p.u0, p.v0, p.u1, p.v0, nu);
    side(p.u0, p.v1, p.u1, p.v1, nu);
    side(p.u0, p.v0, p.u0, p.v1, nv);
    side(p.u1, p.v0, p.u1, p.v1, nv);
  }

  void callBegin(GLenum type) {
    if (nurb_.beginData) {
      nurb_.beginData(type, nurb_.userData);
    } else if (nurb_.begin) {
      nurb_.begin(type);
    }
  }
  void callEnd() {
    if (nurb_.endData) {
      nurb_.endData(nurb_.userData);
    } else if (nurb_.end) {
      nurb_.end();
    }
  }
  // Evaluates every map at (u, v) and reports texture coordinates, colour, normal and vertex.
  void callVertex(const DomainPoint& d) {
    GLfloat position[3] = {0, 0, 0}, normal[3] = {0, 0, 1}, color[4] = {0, 0, 0, 1};
    GLfloat texCoord[4] = {0, 0, 0, 1};
    bool hasNormal = false, hasColor = false, hasTexCoord = false;
    for (const PieceMap& m : *maps_) {
      const Map& map = *m.map;
      const BezierSurfacePiece& p = *m.piece;
      const double s = (d.u - p.u0) / (p.u1 - p.u0), t = (d.v - p.v0) / (p.v1 - p.v0);
      double value[4] = {0, 0, 0, 1}, du[4] = {}, dv[4] = {};
      evaluatePatch(p.points, map.uOrder, map.vOrder, map.dimension, s, t, value, du, dv);
      if (isGeometry(map.type)) {
        const bool rational = map.dimension == 4;
        const double w = rational ? value[3] : 1.0;
        double pu[3], pv[3];
        for (int k = 0; k < 3; ++k) {
          position[k] = static_cast<GLfloat>(value[k] / w);
          // The quotient rule for a rational surface: (H_u - P w_u) / w.
          pu[k] = rational ? (du[k] - value[k] / w * du[3]) / w : du[k];
          pv[k] = rational ? (dv[k] - value[k] / w * dv[3]) / w : dv[k];
        }
        if (!hasNormal) {
          const double n[3] = {pu[1] * pv[2] - pu[2] * pv[1], pu[2] * pv[0] - pu[0] * pv[2],
                               pu[0] * pv[1] - pu[1] * pv[0]};
          const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
          if (length > 0.0) {
            for (int k = 0; k < 3; ++k) normal[k] = static_cast<GLfloat>(n[k] / length);
          }
        }
      } else if (map.type == GL_MAP2_NORMAL) {
        for (int k = 0; k < 3; ++k) normal[k] = static_cast<GLfloat>(value[k]);
        hasNormal = true;
      } else if (map.type == GL_MAP2_COLOR_4) {
        for (int k = 0; k < 4; ++k) color[k] = static_cast<GLfloat>(value[k]);
        hasColor = true;
      } else if (map.type >= GL_MAP2_TEXTURE_COORD_1 && map.type <= GL_MAP2_TEXTURE_COORD_4) {
        for (int k = 0; k < map.dimension; ++k) texCoord[k] = static_cast<GLfloat>(value[k]);
        hasTexCoord = true;
      }
    }
    if (hasTexCoord) reportValue(nurb_.texCoord, nurb_.texCoordData, nurb_.userData, texCoord);
    if (hasColor) reportValue(nurb_.color, nurb_.colorData, nurb_.userData, color);
    reportValue(nurb_.normal, nurb_.normalData, nurb_.userData, normal);
    reportValue(nurb_.vertex, nurb_.vertexData, nurb_.userData, position);
  }

  GLUnurbs& nurb_;
  bool renderer_;
  const std::vector<PieceMap>* maps_ = nullptr;
};

// The trimmed region as closed loops of domain points (the region is on each loop's left).
using Loop = std::vector<PlanarPoint>;

double signedArea(const Loop& loop) {
  double area = 0.0;
  for (size_t k = 0; k < loop.size(); ++k) {
    const PlanarPoint& a = loop[k];
    const PlanarPoint& b = loop[(k + 1) % loop.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return 0.5 * area;
}

// A NURBS trimming curve as a polyline: each Bezier piece sampled `perPiece` times.
void appendNurbsTrim(const Map& map, int perPiece, Loop& loop) {
  const std::vector<BezierCurvePiece> pieces =
      geometry::bezierPiecesOfCurve(map.uOrder, map.uKnots, map.dimension, map.points);
  for (const BezierCurvePiece& piece : pieces) {
    for (int k = 0; k <= perPiece; ++k) {
      double value[3] = {0, 0, 1};
      evaluateBezier(piece.points.data(), map.uOrder, map.dimension, map.dimension,
                     static_cast<double>(k) / perPiece, value, nullptr);
      const double w = map.dimension == 3 && value[2] != 0.0 ? value[2] : 1.0;
      const PlanarPoint p{value[0] / w, value[1] / w};
      if (loop.empty() || !(loop.back() == p)) loop.push_back(p);
    }
  }
}

std::vector<Loop> trimLoops(const GLUnurbs& nurb, int perPiece) {
  std::vector<Loop> loops;
  for (const auto& trim : nurb.trims) {
    Loop loop;
    for (const GLUnurbs::TrimCurve& curve : trim) {
      if (curve.piecewiseLinear) {
        for (size_t k = 0; k + 1 < curve.points.size(); k += 2) {
          const PlanarPoint p{curve.points[k], curve.points[k + 1]};
          if (loop.empty() || !(loop.back() == p)) loop.push_back(p);
        }
      } else {
        appendNurbsTrim(curve.nurbs, perPiece, loop);
      }
    }
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

// The winding number of the loops around a point: inside the region when positive.
int windingAround(const std::vector<Loop>& loops, double x, double y) {
  int winding = 0;
  for (const Loop& loop : loops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const PlanarPoint& a = loop[k];
      const PlanarPoint& b = loop[(k + 1) % loop.size()];
      if (a.y <= y && b.y > y && (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y) > 0) ++winding;
      if (a.y > y && b.y <= y && (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y) < 0) --winding;
    }
  }
  return winding;
}

// Whether any loop edge comes into the rectangle (its bounding box overlaps it).
bool loopsEnter(const std::vector<Loop>& loops, double u0, double u1, double v0, double v1) {
  for (const Loop& loop : loops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const PlanarPoint& a = loop[k];
      const PlanarPoint& b = loop[(k + 1) % loop.size()];
      if (std::max(a.x, b.x) < u0 || std::min(a.x, b.x) > u1) continue;
      if (std::max(a.y, b.y) < v0 || std::min(a.y, b.y) > v1) continue;
      return true;
    }
  }
  return false;
}

// The part of a grid cell inside the trimmed region, as triangles: the cell (counter-clockwise,
// winding 1) and the loops (winding 1 inside the region) overlap where the winding number is 2.
void trimmedCell(const std::vector<Loop>& loops, double u0, double u1, double v0, double v1,
                 std::vector<DomainPoint>& out) {
  std::vector<std::vector<PlanarPoint>> contours{{{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}};
  contours.insert(contours.end(), loops.begin(), loops.end());
  const geometry::PolygonTessellation t =
      geometry::tessellatePolygon(contours, geometry::WindingRule::AbsGeqTwo, false);
  std::vector<PlanarPoint> points;
  for (const auto& c : contours) points.insert(points.end(), c.begin(), c.end());
  for (const auto& created : t.created) points.push_back(created.position);
  for (const auto& triangle : t.triangles) {
    for (int v : triangle.vertices) out.push_back({points[v].x, points[v].y});
  }
}

// The segment a-b clipped to the rectangle (Liang-Barsky); false when nothing is left.
bool clipSegment(PlanarPoint& a, PlanarPoint& b, double u0, double u1, double v0, double v1) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - u0, u1 - a.x, a.y - v0, v1 - a.y};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;
      continue;
    }
    const double r = q[k] / p[k];
    if (p[k] < 0.0) {
      t0 = std::max(t0, r);
    } else {
      t1 = std::min(t1, r);
    }
  }
  if (t0 > t1) return false;
  const PlanarPoint start{a.x + t0 * dx, a.y + t0 * dy}, end{a.x + t1 * dx, a.y + t1 * dy};
  a = start;
  b = end;
  return true;
}

// Splits every map at the union of all maps' breakpoints; the pieces of the maps whose
// rectangles match the geometry's are drawn together.
struct SplitSurface {
  std::vector<std::vector<BezierSurfacePiece>> pieces;  // per map
};

SplitSurface splitMaps(const std::vector<Map>& maps) {
  std::vector<double> uBreaks, vBreaks;
  for (const Map& map : maps) {
    const auto u = geometry::breakpointsOf(map.uOrder, map.uKnots);
    const auto v = geometry::breakpointsOf(map.vOrder, map.vKnots);
    uBreaks.insert(uBreaks.end(), u.begin(), u.end());
    vBreaks.insert(vBreaks.end(), v.begin(), v.end());
  }
  SplitSurface split;
  for (const Map& map : maps) {
    split.pieces.push_back(geometry::bezierPiecesOfSurface(map.uOrder, map.uKnots, map.vOrder,
                                                          map.vKnots, map.dimension, map.points,
                                                          uBreaks, vBreaks));
  }
  return split;
}

}  // namespace

void renderNurbsSurface(GLUnurbs& nurb) {
  // The geometry is the last GL_MAP2_VERTEX_3/4 given; there must be one.
  int geometry = -1;
  for (size_t m = 0; m < nurb.maps.size(); ++m) {
    if (isGeometry(nurb.maps[m].type)) geometry = static_cast<int>(m);
  }
  if (geometry < 0) {
    nurb.reportError(GLU_NURBS_ERROR8);  // missing or extra geometric data
    return;
  }
  // One map of each type, the last one given winning, as in glMap2.
  std::vector<Map> maps;
  for (size_t m = 0; m < nurb.maps.size(); ++m) {
    bool later = false;
    for (size_t n = m + 1; n < nurb.maps.size(); ++n) {
      later |= nurb.maps[n].type == nurb.maps[m].type ||
               (isGeometry(nurb.maps[n].type) && isGeometry(nurb.maps[m].type));
    }
    if (!later) maps.push_back(nurb.maps[m]);
  }
  const auto geometryIt = std::find_if(maps.begin(), maps.end(),
                                       [](const Map& m) { return isGeometry(m.type); });
  const Map& shape = *geometryIt;
  const size_t shapeIndex = static_cast<size_t>(geometryIt - maps.begin());
  const SplitSurface split = splitMaps(maps);
  const std::vector<BezierSurfacePiece>& pieces = split.pieces[shapeIndex];

  // One step per direction for the whole surface: the smallest any piece asks for.
  const NurbsSampler sampler(nurb);
  double uStep = INFINITY, vStep = INFINITY;
  for (const BezierSurfacePiece& p : pieces) {
    const auto steps = sampler.surfaceSteps(p.points, shape.uOrder, shape.vOrder, shape.dimension,
                                            p.u1 - p.u0, p.v1 - p.v0);
    uStep = std::min(uStep, steps[0]);
    vStep = std::min(vStep, steps[1]);
  }

  std::vector<Loop> loops = trimLoops(nurb, 16);
  if (!loops.empty()) {
    // Only holes given: the whole domain is the outer loop.
    double area = 0.0;
    for (const Loop& loop : loops) area += signedArea(loop);
    if (area < 0.0 && !pieces.empty()) {
      const double u0 = pieces.front().u0, v0 = pieces.front().v0;
      const double u1 = pieces.back().u1, v1 = pieces.back().v1;
      loops.push_back({{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}});
    }
  }

  const bool renderer = nurb.mode == GLU_NURBS_RENDERER;
  GLint polygonMode[2] = {GL_FILL, GL_FILL};
  if (renderer) {
    glPushAttrib(GL_EVAL_BIT);
    if (nurb.displayMode == GLU_OUTLINE_POLYGON) {
      glGetIntegerv(GL_POLYGON_MODE, polygonMode);
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    }
  }
  SurfaceOutput output(nurb, renderer);
  for (size_t k = 0; k < pieces.size(); ++k) {
    const BezierSurfacePiece& p = pieces[k];
    if (nurb.culling && sampler.outsideView(p.points, shape.dimension)) continue;
    std::vector<PieceMap> pieceMaps;
    for (size_t m = 0; m < maps.size(); ++m) {
      for (const BezierSurfacePiece& q : split.pieces[m]) {
        if (q.u0 == p.u0 && q.u1 == p.u1 && q.v0 == p.v0 && q.v1 == p.v1) {
          pieceMaps.push_back({&maps[m], &q});
          break;
        }
      }
    }
    const int nu = stepCount(p.u1 - p.u0, uStep), nv = stepCount(p.v1 - p.v0, vStep);
    const bool trimmed = !loops.empty() && loopsEnter(loops, p.u0, p.u1, p.v0, p.v1);
    if (loops.empty() ||
        (!trimmed && windingAround(loops, 0.5 * (p.u0 + p.u1), 0.5 * (p.v0 + p.v1)) > 0)) {
      output.bind(pieceMaps);
      output.grid(p, nu, nv);
      continue;
    }
    if (!trimmed) continue;  // entirely trimmed away
    output.bind(pieceMaps);
    if (nurb.displayMode == GLU_OUTLINE_PATCH) {
      // The trimming loops, clipped to the piece.
      for (const Loop& loop : loops) {
        for (size_t e = 0; e < loop.size(); ++e) {
          PlanarPoint a = loop[e], b = loop[(e + 1) % loop.size()];
          if (clipSegment(a, b, p.u0, p.u1, p.v0, p.v1)) {
            output.emitLineStrip({{a.x, a.y}, {b.x, b.y}});
          }
        }
      }
      continue;
    }
    std::vector<DomainPoint> triangles;
    for (int i = 0; i < nu; ++i) {
      const double u0 = p.u0 + (p.u1 - p.u0) * i / nu, u1 = p.u0 + (p.u1 - p.u0) * (i + 1) / nu;
      for (int j = 0; j < nv; ++j) {
        const double v0 = p.v0 + (p.v1 - p.v0) * j / nv, v1 = p.v0 + (p.v1 - p.v0) * (j + 1) / nv;
        if (loopsEnter(loops, u0, u1, v0, v1)) {
          trimmedCell(loops, u0, u1, v0, v1, triangles);
        } else if (windingAround(loops, 0.5 * (u0 + u1), 0.5 * (v0 + v1)) > 0) {
          SurfaceOutput::cellTriangles(p, nu, nv, i, j, triangles);
        }
      }
    }
    output.emitTriangles(triangles);
  }
  if (renderer) {
    if (nurb.displayMode == GLU_OUTLINE_POLYGON) {
      glPolygonMode(GL_FRONT, static_cast<GLenum>(polygonMode[0]));
      glPolygonMode(GL_BACK, static_cast<GLenum>(polygonMode[1]));
    }
    glPopAttrib();
  }
}

void renderNurbsCurve(GLUnurbs& nurb) {
  int geometry = -1;
  for (size_t m = 0; m < nurb.maps.size(); ++m) {
    if (isGeometry(nurb.maps[m].type)) geometry = static_cast<int>(m);
  }
  if (geometry < 0) {
    nurb.reportError(GLU_NURBS_ERROR8);  // missing or extra geometric data
    return;
  }
  std::vector<double> breaks;
  for (const Map& map : nurb.maps) {
    const auto b = geometry::breakpointsOf(map.uOrder, map.uKnots);
    breaks.insert(breaks.end(), b.begin(), b.end());
  }
  std::vector<std::vector<BezierCurvePiece>> pieces;
  for (const Map& map : nurb.maps) {
    pieces.push_back(
        geometry::bezierPiecesOfCurve(map.uOrder, map.uKnots, map.dimension, map.points, breaks));
  }
  const Map& shape = nurb.maps[geometry];
  const NurbsSampler sampler(nurb);
  double step = INFINITY;
  for (const BezierCurvePiece& p : pieces[geometry]) {
    step = std::min(step, sampler.curveStep(p.points, shape.uOrder, shape.dimension, p.u1 - p.u0));
  }
  const bool renderer = nurb.mode == GLU_NURBS_RENDERER;
  if (renderer) glPushAttrib(GL_EVAL_BIT);
  for (const BezierCurvePiece& p : pieces[geometry]) {
    if (nurb.culling && sampler.outsideView(p.points, shape.dimension)) continue;
    const int n = stepCount(p.u1 - p.u0, step);
    std::vector<std::pair<const Map*, const BezierCurvePiece*>> pieceMaps;
    for (size_t m = 0; m < nurb.maps.size(); ++m) {
      for (const BezierCurvePiece& q : pieces[m]) {
        if (q.u0 == p.u0 && q.u1 == p.u1) {
          pieceMaps.push_back({&nurb.maps[m], &q});
          break;
        }
      }
    }
    if (renderer) {
      for (const auto& [map, piece] : pieceMaps) {
        std::vector<float> points(piece->points.begin(), piece->points.end());
        glMap1f(map->type, static_cast<float>(p.u0), static_cast<float>(p.u1), map->dimension,
                map->uOrder, points.data());
        glEnable(map->type);
      }
      glMapGrid1f(n, static_cast<float>(p.u0), static_cast<float>(p.u1));
      glEvalMesh1(GL_LINE, 0, n);
      continue;
    }
    // Tessellator mode: the line strip's points, each with the other maps' values first.
    if (nurb.beginData) {
      nurb.beginData(GL_LINE_STRIP, nurb.userData);
    } else if (nurb.begin) {
      nurb.begin(GL_LINE_STRIP);
    }
    for (int k = 0; k <= n; ++k) {
      const double t = static_cast<double>(k) / n;
      GLfloat vertex[3] = {0, 0, 0};
      for (const auto& [map, piece] : pieceMaps) {
        double value[4] = {0, 0, 0, 1};
        evaluateBezier(piece->points.data(), map->uOrder, map->dimension, map->dimension, t, value,
                       nullptr);
        if (isGeometry(map->type)) {
          const double w = map->dimension == 4 ? value[3] : 1.0;
          for (int c = 0; c < 3; ++c) vertex[c] = static_cast<GLfloat>(value[c] / w);
          continue;
        }
        GLfloat out[4] = {0, 0, 0, 1};
        for (int c = 0; c < map->dimension; ++c) out[c] = static_cast<GLfloat>(value[c]);
        if (map->type == GL_MAP1_NORMAL) {
          reportValue(nurb.normal, nurb.normalData, nurb.userData, out);
        } else if (map->type == GL_MAP1_COLOR_4) {
          reportValue(nurb.color, nurb.colorData, nurb.userData, out);
        } else if (map->type >= GL_MAP1_TEXTURE_COORD_1 && map->type <= GL_MAP1_TEXTURE_COORD_4) {
          reportValue(nurb.texCoord, nurb.texCoordData, nurb.userData, out);
        }
      }
      reportValue(nurb.vertex, nurb.vertexData, nurb.userData, vertex);
    }
    if (nurb.endData) {
      nurb.endData(nurb.userData);
    } else if (nurb.end) {
      nurb.end();
    }
  }
  if (renderer) glPopAttrib();
}

}  // namespace glass::gl::glu
