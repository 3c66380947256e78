// A GL line segment drawn from its quadrilateral, made once: the tiled rasterizer bins the
// segment by the quad's pixels and draws it tile by tile from the same quad.
#pragma once

#include "glass/raster/line.h"
#include "line_quad.h"

namespace glass::raster {

// The quad of the segment from a to b with the settings' width and framebuffer height
// (makeLineQuad); false when the segment draws nothing whatever the bounds: a position that is
// not finite or beyond the fixed-point range, or a zero length.
bool lineQuadOf(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
                LineQuad& quad);

// The pixels of `bounds` the quad's fragments can be in (the pixel centres in its corners' box).
PixelRect lineQuadPixels(const LineQuad& quad, const PixelRect& bounds);

// rasterizeLine for a segment whose quad lineQuadOf made.
void rasterizeLine(const LineQuad& quad, const WindowVertex& a, const WindowVertex& b,
                   const LineSettings& settings, FragmentSink& sink);

// Draws the fragments of the segment inside settings.bounds, as rasterizeLine does, with the
// stipple counter at the segment's start given as stippleStart (settings.stippleCounter is
// neither read nor advanced). Only the runs inside the bounds are walked, and before them only
// as many as the stipple counter needs, so a segment drawn tile by tile costs about as much as
// drawing it once.
void rasterizeLineSection(const LineQuad& quad, const WindowVertex& a, const WindowVertex& b,
                          const LineSettings& settings, int stippleStart, FragmentSink& sink);

}  // namespace glass::raster
