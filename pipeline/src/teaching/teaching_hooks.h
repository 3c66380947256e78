// The teaching views' hooks in the general drawing path (teaching_view.h): small functions the
// fragment stage and the triangle stage call once per batch or per triangle, only for a draw
// whose context has a view.
#pragma once

#include <cstdint>

#include "glass/raster/fragment.h"
#include "glass/raster/vertex.h"
#include "teaching/teaching_view.h"
#include "vertex/varyings.h"

namespace glass::gl {

struct Context;

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

// Normals: the colour 255 (n + 1) / 2 of the normalized eye-space normal n (black for a zero
// normal, which has no direction). normals_view.cpp
void paintNormal(const float eyeNormal[3], std::uint8_t* rgba);

// Mipmap: the colour of the mipmap level that fragment `index` of the batch sampled on the first
// texture unit with a texture; for GL_*_MIPMAP_LINEAR the two levels' colours mixed as their
// texels are. mipmap_view.cpp
void paintMipmapLevel(const Context& ctx, const raster::FragmentBatch& batch, int index,
                      std::uint8_t* rgba);

// The normals and mipmap views paint each fragment that the fragment stage writes into the colour
// buffer, on its pixel of `colors` (TeachingCanvas::fragmentColors, `width` pixels a row). The
// fragments of a batch lie in one tile, which one thread owns, so pixels of different tiles never
// race. eyeNormal: the fragment's interpolated normal (varying::kEyeNormal).
inline void paintFragmentView(const Context& ctx, TeachingView view, std::uint8_t* colors, int width,
                              const raster::FragmentBatch& batch, int index, const float* eyeNormal) {
  const raster::Fragment& f = batch.fragments[index];
  std::uint8_t* rgba = colors + 4 * (static_cast<std::size_t>(f.y) * static_cast<std::size_t>(width) +
                                     static_cast<std::size_t>(f.x));
  if (view == TeachingView::Normals) {
    // Pixel rectangles (glDrawPixels, glBitmap) carry no normal: they paint nothing.
    if (batch.varyingCount >= varying::kEyeNormal + 3) paintNormal(eyeNormal, rgba);
  } else {
    paintMipmapLevel(ctx, batch, index, rgba);
  }
}

}  // namespace glass::gl
