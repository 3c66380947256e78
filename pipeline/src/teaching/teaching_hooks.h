// The teaching views' hooks in the general drawing path (teaching_view.h): small functions the
// fragment stage and the triangle stage call once per batch or per triangle, only for a draw
// whose context has a view.
#pragma once

#include <cstdint>

#include "glass/raster/fragment.h"
#include "glass/raster/vertex.h"
#include "teaching/teaching_view.h"

namespace glass::gl {

// Overdraw: adds the batch's fragments to their pixels' counts (saturating). The fragments of a
// batch lie in one tile, which one thread owns, so counts of different tiles never race.
inline void countFragments(std::uint16_t* counts, int width, const raster::FragmentBatch& batch) {
  for (int i = 0; i < batch.count; ++i) {
    const raster::Fragment& f = batch.fragments[i];
    std::uint16_t& count = counts[static_cast<std::size_t>(f.y) * static_cast<std::size_t>(width) +
                                  static_cast<std::size_t>(f.x)];
    if (count != UINT16_MAX) ++count;
  }
}

// Wireframe: marks the three edges of a triangle in window coordinates, as rasterized (after
// clipping, perspective division and the viewport).
void markTriangleEdges(TeachingCanvas& canvas, const raster::WindowVertex& a,
                       const raster::WindowVertex& b, const raster::WindowVertex& c);

}  // namespace glass::gl
