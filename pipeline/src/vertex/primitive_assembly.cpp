#include "vertex/primitive_assembly.h"

#include "core/context.h"
#include "primitive/draw_pipeline.h"
#include "vertex/gathered_vertices.h"

namespace glass::gl {

namespace {

// Edge-flag bits for a triangle whose edges a->b, b->c, c->a are boundary edges when flagged.
unsigned edgeBits(bool ab, bool bc, bool ca) {
  return (ab ? 1u : 0u) | (bc ? 2u : 0u) | (ca ? 4u : 0u);
}

// A quadrilateral given in boundary order q0 q1 q2 q3, split into two triangles along the
// diagonal q0-q2, (q0, q1, q2) and (q0, q2, q3), or along q1-q3, (q0, q1, q3) and (q1, q2, q3).
// The specification leaves the split open; it decides how colours interpolate across the quad.
// f0..f3: boundary flags of the edges q0q1, q1q2, q2q3, q3q0.
void drawQuad(DrawPipeline& draw, const PipelineVertex& q0, const PipelineVertex& q1,
              const PipelineVertex& q2, const PipelineVertex& q3, const PipelineVertex& provoking,
              bool alongQ1Q3, bool f0, bool f1, bool f2, bool f3) {
  if (alongQ1Q3) {
    draw.drawTriangle(q0, q1, q3, provoking, edgeBits(f0, false, f3));
    draw.drawTriangle(q1, q2, q3, provoking, edgeBits(f1, f2, false));
  } else {
    draw.drawTriangle(q0, q1, q2, provoking, edgeBits(f0, f1, false));
    draw.drawTriangle(q0, q2, q3, provoking, edgeBits(false, f2, f3));
  }
}

// GL_POLYGON as a fan around its first vertex, which is also its provoking vertex (spec 2.13.7).
// Only the polygon's own edges are boundary edges, each as its starting vertex's flag says.
void drawPolygon(DrawPipeline& draw, const std::vector<PipelineVertex>& p) {
  const size_t n = p.size();
  if (n < 3) return;
  for (size_t i = 1; i + 1 < n; ++i) {
    draw.drawTriangle(p[0], p[i], p[i + 1], p[0],
                      edgeBits(i == 1 && p[0].edgeFlag, p[i].edgeFlag,
                               i + 2 == n && p[i + 1].edgeFlag));
  }
}

// GL_QUADS: each quad v0 v1 v2 v3 with v3 provoking. Mesa splits the quads of a draw call along
// v0-v2 when every vertex lies inside the clip volume and along v1-v3 when some vertex must be
// clipped (its draw module takes a different path then), and along v1-v3 always for
// glDrawElements and in display lists (their vertices reach the draw module indexed). glass
// decides the same way for the quads of one glBegin/glEnd or draw call, so that colours
// interpolate across quads as in Mesa (docs/pipeline.md, "How quads are split", has the numbers).
void drawQuads(DrawPipeline& draw, const std::vector<PipelineVertex>& v, bool needsClipping) {
  for (size_t i = 0; i + 3 < v.size(); i += 4) {
    drawQuad(draw, v[i], v[i + 1], v[i + 2], v[i + 3], v[i + 3], needsClipping, v[i].edgeFlag,
             v[i + 1].edgeFlag, v[i + 2].edgeFlag, v[i + 3].edgeFlag);
  }
}

}  // namespace

bool isPrimitiveMode(GLenum mode) { return mode <= GL_POLYGON; }

void beginPrimitive(Context& ctx, GLenum mode) {
  PrimitiveAssembly& pa = ctx.assembly;
  pa.active = true;
  pa.mode = mode;
  pa.vertexCount = 0;
  pa.pending.clear();
  pa.pendingNeedsClipping = false;
  pa.gathering = false;  // glBegin turns it on (gathered_vertices.h)
  pa.gatheredCount = 0;
  ctx.draw->prepare();
}

// Provoking vertices follow spec 2.13.7 (table 2.6): the last vertex of each point, line,
// triangle and quadrilateral, except GL_LINE_LOOP's closing segment (its first vertex) and
// GL_POLYGON (its first vertex). Edge flags apply to independent triangles, quads and polygons
// only; strips and fans draw every edge (spec 2.6.2).
namespace {

// The independent primitives of `corners` vertices each (GL_TRIANGLES, GL_LINES) that lie whole
// in vertexAt(0 .. count), each given to draw(first vertex's index) straight from the batch;
// the vertices of one begun in an earlier batch go through assembleVertex first. Returns the
// index of the first vertex left over.
template <class VertexAt, class Draw>
int assembleWholePrimitives(Context& ctx, int count, int corners, VertexAt vertexAt, Draw draw) {
  PrimitiveAssembly& pa = ctx.assembly;
  int i = 0;
  for (; i < count && pa.vertexCount % corners != 0; ++i) assembleVertex(ctx, vertexAt(i));
  for (; i + corners <= count; i += corners) {
    pa.vertexCount += corners;
    if (FrameStatistics* statistics = ctx.draw->statistics()) statistics->vertices += corners;
    draw(i);
  }
  return i;
}

// assembleVertices over vertexAt(0 .. count). Whole independent triangles and lines of the
// batch are drawn from it directly; the other vertices go through assembleVertex, which keeps
// copies of those a later vertex needs.
template <class VertexAt>
void assembleInOrder(Context& ctx, int count, VertexAt vertexAt) {
  DrawPipeline& draw = *ctx.draw;
  int i = 0;
  if (ctx.assembly.mode == GL_TRIANGLES) {
    i = assembleWholePrimitives(ctx, count, 3, vertexAt, [&](int k) {
      const PipelineVertex &a = vertexAt(k), &b = vertexAt(k + 1), &c = vertexAt(k + 2);
      draw.drawTriangle(a, b, c, c, edgeBits(a.edgeFlag, b.edgeFlag, c.edgeFlag));
    });
  } else if (ctx.assembly.mode == GL_LINES) {
    i = assembleWholePrimitives(ctx, count, 2, vertexAt, [&](int k) {
      draw.drawLine(vertexAt(k), vertexAt(k + 1), vertexAt(k + 1), DrawPipeline::StippleRun::Alone);
    });
  }
  for (; i < count; ++i) assembleVertex(ctx, vertexAt(i));
}

}  // namespace

void assembleVertices(Context& ctx, const PipelineVertex* vertices, int count) {
  assembleInOrder(ctx, count, [vertices](int i) -> const PipelineVertex& { return vertices[i]; });
}

void assembleVertices(Context& ctx, const PipelineVertex* const* vertices, int count) {
  assembleInOrder(ctx, count, [vertices](int i) -> const PipelineVertex& { return *vertices[i]; });
}

void assembleVertex(Context& ctx, const PipelineVertex& v) {
  PrimitiveAssembly& pa = ctx.assembly;
  DrawPipeline& draw = *ctx.draw;
  PipelineVertex* w = pa.window;
  const int n = pa.vertexCount++;
  if (FrameStatistics* statistics = draw.statistics()) ++statistics->vertices;

  switch (pa.mode) {
    case GL_POINTS:
      draw.drawPoint(v);
      break;
    case GL_LINES:
      if (n % 2 == 0) {
        w[0] = v;
      } else {
        draw.drawLine(w[0], v, v, DrawPipeline::StippleRun::Alone);
      }
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      if (n == 0) {
        pa.first = v;
      } else {
        draw.drawLine(w[0], v, v, n == 1 ? DrawPipeline::StippleRun::First : DrawPipeline::StippleRun::Continued);
      }
      w[0] = v;
      break;
    case GL_TRIANGLES:
      if (n % 3 < 2) {
        w[n % 3] = v;
      } else {
        draw.drawTriangle(w[0], w[1], v, v, edgeBits(w[0].edgeFlag, w[1].edgeFlag, v.edgeFlag));
      }
      break;
    case GL_TRIANGLE_STRIP:
      // Triangle i is (v_i, v_i+1, v_i+2) for even i and (v_i+1, v_i, v_i+2) for odd i, so that
      // all triangles of the strip have the same orientation.
      // w[0], w[1] hold the two vertices before v.
      if (n < 2) {
        w[n] = v;
        break;
      }
      if (n % 2 == 0) {
        draw.drawTriangle(w[0], w[1], v, v, kAllEdges);
      } else {
        draw.drawTriangle(w[1], w[0], v, v, kAllEdges);
      }
      w[0] = w[1];
      w[1] = v;
      break;
    case GL_TRIANGLE_FAN:
      if (n == 0) {
        pa.first = v;
      } else {
        if (n >= 2) draw.drawTriangle(pa.first, w[0], v, v, kAllEdges);
        w[0] = v;
      }
      break;
    case GL_QUADS:
      // Held until glEnd: see drawQuads.
      pa.pending.push_back(v);
      pa.pendingNeedsClipping = pa.pendingNeedsClipping || draw.needsClipping(v);
      break;
    case GL_QUAD_STRIP:
      // Quad i has the boundary v_2i, v_2i+1, v_2i+3, v_2i+2 and the provoking vertex v_2i+3.
      if (n >= 3 && n % 2 == 1) {
        // Split along v_2i-v_2i+3, as Mesa splits quad strips whether clipped or not.
        drawQuad(draw, w[0], w[1], v, w[2], v, false, true, true, true, true);
        w[0] = w[2];
        w[1] = v;
      } else if (n < 3) {
        w[n] = v;
      } else {
        w[2] = v;
      }
      break;
    case GL_POLYGON:
      pa.pending.push_back(v);
      break;
    default:
      break;
  }
}

void endPrimitive(Context& ctx) {
  finishGathering(ctx);
  PrimitiveAssembly& pa = ctx.assembly;
  if (pa.mode == GL_LINE_LOOP && pa.vertexCount >= 2) {
    ctx.draw->drawLine(pa.window[0], pa.first, pa.first, DrawPipeline::StippleRun::Continued);
  } else if (pa.mode == GL_POLYGON) {
    drawPolygon(*ctx.draw, pa.pending);
  } else if (pa.mode == GL_QUADS) {
    drawQuads(*ctx.draw, pa.pending, pa.pendingNeedsClipping || ctx.lists.callDepth > 0);
  }
  pa.pending.clear();
  pa.active = false;
  ctx.draw->finishIfReadingContext();
}

}  // namespace glass::gl
