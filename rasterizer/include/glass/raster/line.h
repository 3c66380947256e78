// GL line segments (spec section 3.4): width 1 by the diamond-exit rule, wider lines as the
// specification's non-antialiased wide-line rule (a column or row of `width` pixels per step
// along the major axis).
#pragma once

#include "glass/raster/fragment.h"
#include "glass/raster/vertex.h"

namespace glass::raster {

struct LineSettings {
  PixelRect bounds;
  int varyingCount = 0;
  float width = 1.0f;
  bool perspectiveCorrect = true;
  double depthBias = 0.0;      // polygon offset for GL_LINE polygon mode
  // Line stipple (glLineStipple): repeat factor 0 disables it.
  int stippleFactor = 0;
  unsigned short stipplePattern = 0xFFFF;
  // A line strip continues its stipple counter across segments; the pipeline keeps it here.
  int* stippleCounter = nullptr;
  // For GL_LINE_STRIP/LOOP the shared vertex of consecutive segments is drawn once: the last
  // pixel of a segment is never drawn by the diamond-exit rule, so no special case is needed.
  // The height of the framebuffer drawn into. Which pixel a line takes where it passes exactly
  // between two (a tie) depends on float rounding in Mesa's line setup, which numbers rows
  // downwards from the framebuffer's top; glass does the same arithmetic on the same numbers when
  // it knows the height (0: rows numbered downwards from y = 0, which differs from Mesa in rare
  // rounding cases). See rasterizer/src/line_quad.cpp.
  int framebufferHeight = 0;
};

void rasterizeLine(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
                   FragmentSink& sink);

struct PointSettings {
  PixelRect bounds;
  int varyingCount = 0;
  float size = 1.0f;  // non-antialiased: a size x size square centred on the point (spec 3.3)
  double depthBias = 0.0;
};

void rasterizePoint(const WindowVertex& v, const PointSettings& settings, FragmentSink& sink);

}  // namespace glass::raster
