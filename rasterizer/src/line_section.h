// The part of a GL line segment inside a screen tile, for the tiled rasterizer.
#pragma once

#include "glass/raster/line.h"

namespace glass::raster {

// Draws the fragments of the segment inside settings.bounds, as rasterizeLine does, with the
// stipple counter at the segment's start given as stippleStart (settings.stippleCounter is
// neither read nor advanced). Only the runs inside the bounds are walked, and before them only
// as many as the stipple counter needs, so a segment drawn tile by tile costs about as much as
// drawing it once.
void rasterizeLineSection(const WindowVertex& a, const WindowVertex& b,
                          const LineSettings& settings, int stippleStart, FragmentSink& sink);

}  // namespace glass::raster
