// Non-antialiased points (OpenGL 1.5 spec, section 3.3).
//
// The size is rounded to an integer w (at least 1): the specification says "the nearest integer"
// and leaves halves open; glass rounds them down, as Mesa's llvmpipe does (the size snapped to
// 1/256, then (s + 127) / 256), so sizes 1.5, 2.5 and 3.5 give 1, 2 and 3 pixels, 1.6 gives 2.
// The point covers the w x w square of pixels
// centred on (floor(x) + 1/2, floor(y) + 1/2) when w is odd and on (floor(x + 1/2),
// floor(y + 1/2)) when w is even, that is the pixels
//   odd w:  floor(x) - (w - 1) / 2  ..  floor(x) + (w - 1) / 2
//   even w: floor(x + 1/2) - w / 2  ..  floor(x + 1/2) + w / 2 - 1
// (and the same in y). Every fragment takes the vertex's depth and varyings. The position is first
// snapped to 1/256 pixel, as for lines and triangles, so a point and a line through the same
// vertex agree on which pixel holds it.
#include <algorithm>
#include <cmath>

#include "glass/raster/depth_value.h"
#include "glass/raster/line.h"
#include "subpixel.h"

namespace glass::raster {
namespace {

// First pixel of the point's run along one axis; `fixed` is the coordinate in 24.8 fixed point.
int64_t firstPixel(int64_t fixed, int width) {
  if (width % 2 == 1) return (fixed >> kSubpixelBits) - (width - 1) / 2;
  return ((fixed + kSubpixelHalf) >> kSubpixelBits) - width / 2;
}

}  // namespace

void rasterizePoint(const WindowVertex& v, const PointSettings& settings, FragmentSink& sink) {
  if (!isRasterizableCoordinate(v.x) || !isRasterizableCoordinate(v.y)) return;
  // The size is taken between 1 and 2^20 first (NaN gives 1), which keeps the conversion to
  // integers defined; a point that size already covers any framebuffer.
  const float size = std::fmin(std::fmax(settings.size, 1.0f), 1048576.0f);
  const int64_t sizeIn256ths = static_cast<int64_t>(std::floor(size * 256.0f + 0.5f));
  const int width = static_cast<int>(std::max<int64_t>(1, (sizeIn256ths + 127) >> kSubpixelBits));
  const int64_t x0 = firstPixel(snapToSubpixel(v.x), width);
  const int64_t y0 = firstPixel(snapToSubpixel(v.y), width);
  const PixelRect& r = settings.bounds;
  const int64_t xs = std::max<int64_t>(x0, r.x0), xe = std::min<int64_t>(x0 + width, r.x1);
  const int64_t ys = std::max<int64_t>(y0, r.y0), ye = std::min<int64_t>(y0 + width, r.y1);
  if (xs >= xe || ys >= ye) return;

  const int varyingCount = std::clamp(settings.varyingCount, 0, kMaxVaryings);
  constexpr int kBatchSize = 64;
  Fragment fragments[kBatchSize];
  int count = 0;
  Fragment prototype;
  prototype.depth = depthValue(double(v.z) + settings.depthBias);
  for (int k = 0; k < varyingCount; ++k) prototype.varyings[k] = v.varyings[k];
  auto flush = [&] {
    FragmentBatch batch;
    batch.fragments = fragments;
    batch.count = count;
    batch.varyingCount = varyingCount;
    sink.processFragments(batch);
    count = 0;
  };
  for (int64_t y = ys; y < ye; ++y)
    for (int64_t x = xs; x < xe; ++x) {
      Fragment& f = fragments[count++];
      f.x = static_cast<int>(x);
      f.y = static_cast<int>(y);
      f.depth = prototype.depth;
      std::copy(prototype.varyings, prototype.varyings + varyingCount, f.varyings);
      if (count == kBatchSize) flush();
    }
  if (count > 0) flush();
}

}  // namespace glass::raster
