#include "pixels/pixel_fragments.h"

#include <algorithm>
#include <cmath>

#include "core/context.h"
#include "core/float_to_int.h"
#include "fragment/fragment_processor.h"
#include "glass/raster/depth_value.h"
#include "glass/raster/fragment.h"
#include "pixels/imaging_pipeline.h"
#include "pixels/pixel_transfer.h"
#include "texture/client_pixels.h"
#include "vertex/varyings.h"

namespace glass::gl {

namespace {

// The pixels fragments may reach: the framebuffer, within the scissor box when the scissor test
// is on (spec 4.1.2).
raster::PixelRect writableRect(const Context& ctx) {
  raster::PixelRect r{0, 0, ctx.framebuffer.width(), ctx.framebuffer.height()};
  const FragmentState& f = ctx.fragment;
  if (f.scissorTest) {
    r.x0 = std::max(r.x0, f.scissor.x);
    r.y0 = std::max(r.y0, f.scissor.y);
    r.x1 = static_cast<int>(std::min<long long>(r.x1, static_cast<long long>(f.scissor.x) + f.scissor.width));
    r.y1 = static_cast<int>(std::min<long long>(r.y1, static_cast<long long>(f.scissor.y) + f.scissor.height));
  }
  return r;
}


// One axis of a zoomed image: image pixels 0 .. count-1 from the pixel corner `origin`, each
// `zoom` pixels wide (negative: towards smaller coordinates).
struct ZoomedAxis {
  double origin, zoom;
  int count;
  int first = 0, end = 0;  // window pixels [first, end) that show some image pixel

  ZoomedAxis(double corner, float z, int n, int lo, int hi) : origin(corner), zoom(z), count(n) {
    // A zero, infinite or NaN zoom (glPixelZoom accepts any float) draws nothing.
    if (zoom == 0.0 || !std::isfinite(zoom) || !std::isfinite(origin) || count <= 0) return;
    // Window pixel i shows image pixel floor((i + 1/2 - origin) / zoom) when that is in
    // [0, count): i + 1/2 in [origin, origin + count zoom) (or the reverse for zoom < 0).
    const double a = origin, b = origin + count * zoom;
    const double low = std::min(a, b), high = std::max(a, b);
    const double firstPixel = zoom > 0.0 ? std::ceil(low - 0.5) : std::floor(low - 0.5) + 1.0;
    const double endPixel = zoom > 0.0 ? std::ceil(high - 0.5) : std::floor(high - 0.5) + 1.0;
    first = static_cast<int>(std::clamp<double>(firstPixel, lo, hi));
    end = static_cast<int>(std::clamp<double>(endPixel, lo, hi));
  }
  int source(int window) const {
    const double n = std::floor((window + 0.5 - origin) / zoom);
    return static_cast<int>(std::clamp<double>(n, 0.0, count - 1));
  }
};

// The raster position rounded to the nearest pixel corner (halves upward), as Mesa does.
int roundedCorner(float coordinate) { return floorToPixel(double(coordinate + 0.5f)); }

// Collects fragments with the raster position's data and hands them to the fragment stage in
// batches.
class FragmentEmitter {
 public:
  explicit FragmentEmitter(Context& ctx) {
    processor_.prepare(ctx, false);
    const RasterPositionState& r = ctx.rasterPosition;
    prototype_.depth = raster::depthValue(r.window[2]);
    for (float& v : prototype_.varyings) v = 0.0f;
    for (int k = 0; k < 4; ++k) {
      prototype_.varyings[varying::kPrimaryColor + k] = r.color[k];
    }
    for (int u = 0; u < kTextureUnitCount; ++u) {
      for (int k = 0; k < 4; ++k)
        prototype_.varyings[varying::texCoordSlot(u) + k] = r.texCoord[u][k];
    }
    // A fog coordinate taken as the raster distance may be negative; fog uses its magnitude, as
    // for vertices (fragment/fog_hooks.h, fogCoordinate).
    prototype_.varyings[varying::kFogCoordinate] = std::fabs(r.distance);
  }
  ~FragmentEmitter() { flush(); }
  FragmentEmitter(const FragmentEmitter&) = delete;
  FragmentEmitter& operator=(const FragmentEmitter&) = delete;

  raster::Fragment& next(int x, int y) {
    if (count_ == kBatchSize) flush();
    raster::Fragment& f = fragments_[count_++];
    f = prototype_;
    f.x = x;
    f.y = y;
    return f;
  }

 private:
  static constexpr int kBatchSize = 64;

  void flush() {
    if (count_ == 0) return;
    raster::FragmentBatch batch;
    batch.fragments = fragments_;
    batch.count = count_;
    batch.varyingCount = varying::countForTextureUnits(kTextureUnitCount);
    processor_.processFragments(batch);
    count_ = 0;
  }

  FragmentProcessor processor_;
  raster::Fragment prototype_{};
  raster::Fragment fragments_[kBatchSize];
  int count_ = 0;
};

// The image's two axes on the window: from the raster position's pixel corner, moved by the
// zoomed size of the pixels before the image's first column and row.
ZoomedAxis columnsOf(const Context& ctx, const FragmentImage& image, const raster::PixelRect& bounds) {
  const float zoom = ctx.pixelTransfer.zoomX;
  return ZoomedAxis(roundedCorner(ctx.rasterPosition.window[0]) + double(zoom) * image.column0, zoom,
                    image.width, bounds.x0, bounds.x1);
}
ZoomedAxis rowsOf(const Context& ctx, const FragmentImage& image, const raster::PixelRect& bounds) {
  const float zoom = ctx.pixelTransfer.zoomY;
  return ZoomedAxis(roundedCorner(ctx.rasterPosition.window[1]) + double(zoom) * image.row0, zoom,
                    image.height, bounds.y0, bounds.y1);
}

}  // namespace

void drawImageFragments(Context& ctx, const FragmentImage& image) {
  const raster::PixelRect bounds = writableRect(ctx);
  const ZoomedAxis xs = columnsOf(ctx, image, bounds);
  const ZoomedAxis ys = rowsOf(ctx, image, bounds);
  if (xs.first >= xs.end || ys.first >= ys.end) return;

  FragmentEmitter emitter(ctx);
  for (int y = ys.first; y < ys.end; ++y) {
    const size_t row = static_cast<size_t>(ys.source(y)) * static_cast<size_t>(image.width);
    for (int x = xs.first; x < xs.end; ++x) {
      const size_t pixel = row + static_cast<size_t>(xs.source(x));
      raster::Fragment& f = emitter.next(x, y);
      if (image.colors) {
        for (int k = 0; k < 4; ++k) f.varyings[varying::kPrimaryColor + k] = image.colors[pixel * 4 + k];
      }
      if (image.depths) f.depth = raster::depthValue(image.depths[pixel]);
    }
  }
}

bool drawPixelBytes(Context& ctx, const void* pixels, int width, int height, GLenum format, GLenum type,
                    const PixelPacking& unpack) {
  if (type != GL_UNSIGNED_BYTE || !isColorFormat(format) || width <= 0 || height <= 0) return false;
  if (ctx.renderMode.mode != GL_RENDER || !ctx.rasterPosition.valid) return false;
  if (ctx.pixelTransfer.zoomX != 1.0f || ctx.pixelTransfer.zoomY != 1.0f) return false;
  if (!colorTransferChangesNothing(ctx.pixelTransfer) || imagingActive(ctx.imaging)) return false;
  FragmentProcessor processor;
  processor.prepare(ctx, false);
  if (!processor.storesColorsAsGiven()) return false;

  const raster::PixelRect bounds = writableRect(ctx);
  FragmentImage image;
  image.width = width;
  image.height = height;
  const ZoomedAxis xs = columnsOf(ctx, image, bounds);
  const ZoomedAxis ys = rowsOf(ctx, image, bounds);
  // Without zoom the visible columns show consecutive image columns.
  const int count = xs.end - xs.first;
  for (int y = ys.first; y < ys.end; ++y) {
    uint8_t* row = ctx.framebuffer.colorAt(xs.first, y);
    unpackByteColorSpan(pixels, count, width, xs.source(xs.first), ys.source(y), format, type, unpack, row);
    // Without alpha bitplanes the stored alpha stays 255, as the fragment stage stores it.
    if (!ctx.buffers.colorAlpha) {
      for (int i = 0; i < count; ++i) row[4 * i + 3] = 255;
    }
  }
  return true;
}

void drawStencilImage(Context& ctx, const FragmentImage& image) {
  const raster::PixelRect bounds = writableRect(ctx);
  const ZoomedAxis xs = columnsOf(ctx, image, bounds);
  const ZoomedAxis ys = rowsOf(ctx, image, bounds);
  const int width = image.width;
  const int32_t* indices = image.stencil;
  // Spec 4.3.1: the index's low bits (as many as the stencil buffer has) are written through the
  // stencil write mask.
  const unsigned writeMask = ctx.fragment.stencilWriteMask & 0xFFu;
  for (int y = ys.first; y < ys.end; ++y) {
    const size_t row = static_cast<size_t>(ys.source(y)) * static_cast<size_t>(width);
    for (int x = xs.first; x < xs.end; ++x) {
      const unsigned value = static_cast<unsigned>(indices[row + static_cast<size_t>(xs.source(x))]) & 0xFFu;
      uint8_t* s = ctx.framebuffer.stencilAt(x, y);
      *s = static_cast<uint8_t>((*s & ~writeMask) | (value & writeMask));
    }
  }
}

void drawBitmapFragments(Context& ctx, int xll, int yll, int width, int height, const uint8_t* bits) {
  const raster::PixelRect bounds = writableRect(ctx);
  const int x0 = std::max(bounds.x0, xll), x1 = static_cast<int>(std::min<long long>(bounds.x1, static_cast<long long>(xll) + width));
  const int y0 = std::max(bounds.y0, yll), y1 = static_cast<int>(std::min<long long>(bounds.y1, static_cast<long long>(yll) + height));
  if (x0 >= x1 || y0 >= y1) return;
  FragmentEmitter emitter(ctx);
  for (int y = y0; y < y1; ++y) {
    const uint8_t* row = bits + static_cast<size_t>(y - yll) * static_cast<size_t>(width);
    for (int x = x0; x < x1; ++x) {
      if (row[x - xll]) emitter.next(x, y);
    }
  }
}

}  // namespace glass::gl
