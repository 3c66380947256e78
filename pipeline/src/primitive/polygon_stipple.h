// Polygon stipple (OpenGL 1.5 specification, section 3.5.2): with GL_POLYGON_STIPPLE enabled, a
// fragment of a filled polygon at window (x_w, y_w) is kept only when bit (x_w mod 32, y_w mod 32)
// of the 32 x 32 stipple pattern is 1. Row 0 of the pattern is the first row glPolygonStipple
// unpacks (like a glBitmap image), bit 0 of a row is its first column. Points, lines and
// polygons drawn as points or lines are not stippled.
#pragma once

#include <cstdint>

#include "glass/raster/fragment.h"

namespace glass::gl {

struct PolygonStipplePattern {
  // rows[y] bit x: the pattern's bit at column x of row y. Initially all ones (table 6.13).
  uint32_t rows[32] = {~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u,
                       ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u,
                       ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u};

  bool covers(int x, int y) const { return (rows[y & 31] >> (x & 31)) & 1u; }
};

// A fragment sink in front of another that lets through only the fragments the pattern covers.
class PolygonStippleFilter final : public raster::FragmentSink {
 public:
  void prepare(const PolygonStipplePattern& pattern, raster::FragmentSink& next) {
    pattern_ = &pattern;
    next_ = &next;
  }
  void processFragments(const raster::FragmentBatch& batch) override;

 private:
  const PolygonStipplePattern* pattern_ = nullptr;
  raster::FragmentSink* next_ = nullptr;
};

}  // namespace glass::gl
