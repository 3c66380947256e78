// glEvalCoord, glEvalPoint and glEvalMesh (spec 5.1).
//
// An evaluation computes every enabled map of its dimension at (u, v), mapped to [0, 1] by each
// map's domain, and issues a vertex "as if" glColor, glNormal, glTexCoord and glVertex had been
// called with the results, except that the current colour, normal and texture coordinates are not
// changed: they are set for the one vertex and restored afterwards. Without an enabled vertex map
// nothing happens.
//
// GL_AUTO_NORMAL computes the normal of two-dimensional vertex maps as the spec defines it,
// n = (dp/du x dp/dv) / |dp/du x dp/dv|, with p the vertex after division by w for
// GL_MAP2_VERTEX_4, so its derivatives follow the quotient rule (the library's
// BezierSurface::normal). Where the cross product vanishes because a row of control points
// collapses to one point, the spec leaves the normal undefined (Mesa sends a zero normal); glass
// sends the limit of the normal from inside the patch, which is what a lit sphere pole or teapot
// lid needs.
//
// GL_MAP1_INDEX and GL_MAP2_INDEX are kept, enabled and queried like the other maps, but glass has
// only RGBA mode, where a colour index is ignored (spec 2.7), so they produce nothing.
#include <algorithm>
#include <vector>

#include "core/context.h"
#include "evaluators/evaluator_commands.h"
#include "evaluators/map_targets.h"
#include "lighting/lighting_hooks.h"
#include "primitive/draw_pipeline.h"
#include "vertex/immediate_mode.h"
#include "vertex/primitive_assembly.h"
#include "vertex/vertex_stage.h"

namespace glass::gl {

namespace {

// The parameter in [0, 1] of a domain value: u' = (u - u1) / (u2 - u1).
double unitParameter(double value, double lo, double hi) { return (value - lo) / (hi - lo); }

// The value of grid point i of n on [lo, hi]: i * (hi - lo) / n + lo, and hi itself for i = n
// (spec 5.1: "if i = n, then u2 is used").
double gridValue(int i, int n, double lo, double hi) {
  if (i == n) return hi;
  const double step = (hi - lo) / static_cast<double>(n);
  return static_cast<double>(i) * step + lo;
}

// Sets the current attributes to those of an evaluated vertex and puts the old ones back when it
// goes out of scope.
class EvaluatedAttributes {
 public:
  EvaluatedAttributes(Context& ctx, const EvaluatedVertex& vertex) : ctx_(ctx), saved_(ctx.current) {
    if (vertex.hasColor) {
      for (int i = 0; i < 4; ++i) ctx.current.color[i] = static_cast<float>(vertex.color[i]);
      onCurrentColorChanged(ctx);  // glColorMaterial follows the evaluated colour, as after glColor
    }
    if (vertex.hasNormal)
      for (int i = 0; i < 3; ++i) ctx.current.normal[i] = static_cast<float>(vertex.normal[i]);
    if (vertex.hasTexCoord)
      // Evaluated texture coordinates are unit 0's, as glTexCoord's are.
      for (int i = 0; i < 4; ++i)
        ctx.current.texCoord[0][i] = static_cast<float>(vertex.texCoord[i]);
    colorChanged_ = vertex.hasColor;
  }
  ~EvaluatedAttributes() {
    ctx_.current = saved_;
    if (colorChanged_) onCurrentColorChanged(ctx_);
  }
  EvaluatedAttributes(const EvaluatedAttributes&) = delete;
  EvaluatedAttributes& operator=(const EvaluatedAttributes&) = delete;

 private:
  Context& ctx_;
  CurrentState saved_;
  bool colorChanged_ = false;
};

// Of several enabled texture maps only the one with the most coordinates is evaluated (spec 5.1).
int enabledTextureMap(const std::array<bool, kMapKindCount>& enabled) {
  for (MapKind kind : {MapKind::TextureCoord4, MapKind::TextureCoord3, MapKind::TextureCoord2, MapKind::TextureCoord1})
    if (enabled[mapIndex(kind)]) return mapIndex(kind);
  return -1;
}

// GL_MAP*_VERTEX_4 overrides GL_MAP*_VERTEX_3; -1 when neither is enabled.
int enabledVertexMap(const std::array<bool, kMapKindCount>& enabled) {
  if (enabled[mapIndex(MapKind::Vertex4)]) return mapIndex(MapKind::Vertex4);
  if (enabled[mapIndex(MapKind::Vertex3)]) return mapIndex(MapKind::Vertex3);
  return -1;
}

// TexCoord1 .. TexCoord4: the coordinates a map does not give are t = r = 0, q = 1.
glm::dvec4 completeTexCoord(const glm::dvec4& t, int count) {
  return {t.x, count > 1 ? t.y : 0.0, count > 2 ? t.z : 0.0, count > 3 ? t.w : 1.0};
}

void sendVertex(Context& ctx, const EvaluatedVertex& vertex) {
  EvaluatedAttributes attributes(ctx, vertex);
  vertexCommand(ctx, static_cast<float>(vertex.object.x), static_cast<float>(vertex.object.y),
                static_cast<float>(vertex.object.z), static_cast<float>(vertex.object.w));
}

// One grid point of glEvalMesh2(GL_FILL) through the vertex stage; false without a vertex map.
bool processGridVertex(Context& ctx, double u, double v, PipelineVertex& out) {
  EvaluatedVertex vertex;
  if (!evaluateMaps2(ctx, u, v, vertex)) return false;
  EvaluatedAttributes attributes(ctx, vertex);
  const float object[4] = {static_cast<float>(vertex.object.x), static_cast<float>(vertex.object.y),
                           static_cast<float>(vertex.object.z), static_cast<float>(vertex.object.w)};
  processVertex(ctx, ctx.draw->vertexSetup(), object, out);
  out.edgeFlag = ctx.current.edgeFlag;
  return true;
}

// glEvalMesh2(GL_FILL) is, by the spec, a GL_QUAD_STRIP per grid row with the vertices
// (u_j, v_i), (u_j, v_i+1) for j = i1..i2. Each quad is drawn here as the two triangles Mesa's
// evaluator draws (a triangle strip over the same vertices, split along (u_j, v_i+1)-(u_j+1, v_i)),
// so that smooth shading interpolates as in Mesa, with the quad strip's provoking vertex
// (u_j+1, v_i+1) for flat shading and only the quad's own edges as boundary edges.
void fillGrid(Context& ctx, int i1, int i2, int j1, int j2) {
  const MapGrid2& grid = ctx.evaluators.attributes.grid2;
  if (i2 < i1 || j2 <= j1) return;
  const std::size_t columns = static_cast<std::size_t>(i2 - i1 + 1);
  std::vector<PipelineVertex> lower(columns), upper(columns);
  const auto evaluateRow = [&](int j, std::vector<PipelineVertex>& row) {
    const double v = gridValue(j, grid.segmentsV, grid.v1, grid.v2);
    for (std::size_t c = 0; c < columns; ++c) {
      const double u = gridValue(i1 + static_cast<int>(c), grid.segmentsU, grid.u1, grid.u2);
      if (!processGridVertex(ctx, u, v, row[c])) return false;
    }
    return true;
  };
  beginPrimitive(ctx, GL_QUAD_STRIP);
  DrawPipeline& draw = *ctx.draw;
  if (evaluateRow(j1, lower)) {
    for (int j = j1; j < j2; ++j) {
      evaluateRow(j + 1, upper);
      for (std::size_t c = 0; c + 1 < columns; ++c) {
        const PipelineVertex &a = lower[c], &b = lower[c + 1], &cc = upper[c + 1], &d = upper[c];
        draw.drawTriangle(a, d, b, cc, 1u | 4u);   // edges a-d and b-a are the quad's
        draw.drawTriangle(b, d, cc, cc, 2u | 4u);  // edges d-c and c-b
      }
      std::swap(lower, upper);
    }
  }
  endPrimitive(ctx);
}

}  // namespace

bool evaluateMaps1(const Context& ctx, double u, EvaluatedVertex& out) {
  const EvaluatorAttributes& a = ctx.evaluators.attributes;
  const auto& maps = ctx.evaluators.maps1;
  const int vertexMap = enabledVertexMap(a.map1Enabled);
  if (vertexMap < 0) return false;
  const auto at = [&](int index) {
    const Map1& map = maps[index];
    return map.curve.evaluateHomogeneous(unitParameter(u, map.u1, map.u2));
  };
  out = EvaluatedVertex{};
  if ((out.hasColor = a.map1Enabled[mapIndex(MapKind::Color4)])) out.color = at(mapIndex(MapKind::Color4));
  if ((out.hasNormal = a.map1Enabled[mapIndex(MapKind::Normal)])) out.normal = glm::dvec3(at(mapIndex(MapKind::Normal)));
  if (const int texture = enabledTextureMap(a.map1Enabled); texture >= 0) {
    out.hasTexCoord = true;
    out.texCoord = completeTexCoord(at(texture), mapComponents(static_cast<MapKind>(texture)));
  }
  out.object = at(vertexMap);
  return true;
}

bool evaluateMaps2(const Context& ctx, double u, double v, EvaluatedVertex& out) {
  const EvaluatorAttributes& a = ctx.evaluators.attributes;
  const auto& maps = ctx.evaluators.maps2;
  const int vertexMap = enabledVertexMap(a.map2Enabled);
  if (vertexMap < 0) return false;
  const auto at = [&](int index) {
    const Map2& map = maps[index];
    return map.surface.evaluateHomogeneous(unitParameter(u, map.u1, map.u2), unitParameter(v, map.v1, map.v2));
  };
  out = EvaluatedVertex{};
  if ((out.hasColor = a.map2Enabled[mapIndex(MapKind::Color4)])) out.color = at(mapIndex(MapKind::Color4));
  if (a.autoNormal) {
    // The library differentiates by the unit parameters; d/du = d/du' / (u2 - u1), so a reversed
    // domain turns the normal around.
    const Map2& map = maps[vertexMap];
    const double orientation = (map.u2 - map.u1) * (map.v2 - map.v1) < 0.0 ? -1.0 : 1.0;
    out.hasNormal = true;
    out.normal = orientation * map.surface.normal(unitParameter(u, map.u1, map.u2), unitParameter(v, map.v1, map.v2));
  } else if ((out.hasNormal = a.map2Enabled[mapIndex(MapKind::Normal)])) {
    out.normal = glm::dvec3(at(mapIndex(MapKind::Normal)));
  }
  if (const int texture = enabledTextureMap(a.map2Enabled); texture >= 0) {
    out.hasTexCoord = true;
    out.texCoord = completeTexCoord(at(texture), mapComponents(static_cast<MapKind>(texture)));
  }
  out.object = at(vertexMap);
  return true;
}

void evalCoord1Command(Context& ctx, double u) {
  EvaluatedVertex vertex;
  if (evaluateMaps1(ctx, u, vertex)) sendVertex(ctx, vertex);
}

void evalCoord2Command(Context& ctx, double u, double v) {
  EvaluatedVertex vertex;
  if (evaluateMaps2(ctx, u, v, vertex)) sendVertex(ctx, vertex);
}

void evalPoint1Command(Context& ctx, int i) {
  const MapGrid1& grid = ctx.evaluators.attributes.grid1;
  evalCoord1Command(ctx, gridValue(i, grid.segments, grid.u1, grid.u2));
}

void evalPoint2Command(Context& ctx, int i, int j) {
  const MapGrid2& grid = ctx.evaluators.attributes.grid2;
  evalCoord2Command(ctx, gridValue(i, grid.segmentsU, grid.u1, grid.u2), gridValue(j, grid.segmentsV, grid.v1, grid.v2));
}

void evalMesh1Command(Context& ctx, GLenum mode, int i1, int i2) {
  if (rejectInsideBeginEnd(ctx)) return;
  if (mode != GL_POINT && mode != GL_LINE) return recordError(ctx, GL_INVALID_ENUM);
  beginPrimitive(ctx, mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP);
  for (int i = i1; i <= i2; ++i) evalPoint1Command(ctx, i);
  endPrimitive(ctx);
}

void evalMesh2Command(Context& ctx, GLenum mode, int i1, int i2, int j1, int j2) {
  if (rejectInsideBeginEnd(ctx)) return;
  switch (mode) {
    case GL_POINT:
      beginPrimitive(ctx, GL_POINTS);
      for (int j = j1; j <= j2; ++j)
        for (int i = i1; i <= i2; ++i) evalPoint2Command(ctx, i, j);
      endPrimitive(ctx);
      return;
    case GL_LINE:
      // A line strip along u for every grid row, then one along v for every column.
      for (int j = j1; j <= j2; ++j) {
        beginPrimitive(ctx, GL_LINE_STRIP);
        for (int i = i1; i <= i2; ++i) evalPoint2Command(ctx, i, j);
        endPrimitive(ctx);
      }
      for (int i = i1; i <= i2; ++i) {
        beginPrimitive(ctx, GL_LINE_STRIP);
        for (int j = j1; j <= j2; ++j) evalPoint2Command(ctx, i, j);
        endPrimitive(ctx);
      }
      return;
    case GL_FILL:
      fillGrid(ctx, i1, i2, j1, j2);
      return;
    default:
      recordError(ctx, GL_INVALID_ENUM);
  }
}

}  // namespace glass::gl
