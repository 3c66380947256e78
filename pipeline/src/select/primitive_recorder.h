// The last stage of the primitive pipeline in GL_SELECT and GL_FEEDBACK render modes (spec 5.2,
// 5.3): primitives arrive clipped and in window coordinates, after culling, flat shading and
// two-sided colour selection, and are recorded instead of rasterized.
//
// Selection: every vertex of the primitive widens the pending hit's depth range.
// Feedback: a token and the vertices, as Mesa's draw module emits them: a polygon is a fan of
// triangles, each GL_POLYGON_TOKEN 3; a line is GL_LINE_RESET_TOKEN when it starts a new line
// (where the line stipple restarts), GL_LINE_TOKEN otherwise. Colours are the vertex colours the
// rasterizer would interpolate; texture coordinates are the vertex's when texturing is enabled
// (the vertex stage computes them only then) and the current texture coordinates otherwise.
#pragma once

#include <GL/gl.h>

#include "glass/raster/vertex.h"

namespace glass::gl {

struct Context;

class PrimitiveRecorder {
 public:
  // texCoordVaryings: the window vertices carry texture coordinates (texturing is on).
  void prepare(Context& ctx, bool texCoordVaryings);

  void point(const raster::WindowVertex& v);
  void line(const raster::WindowVertex& a, const raster::WindowVertex& b, bool startsLine);
  // A clipped polygon of count >= 3 vertices in window coordinates.
  void polygon(const raster::WindowVertex* v, int count);

 private:
  void vertex(const raster::WindowVertex& v);

  Context* ctx_ = nullptr;
  bool selecting_ = false;
  bool texCoordVaryings_ = false;
};

}  // namespace glass::gl
