// GL line segments (OpenGL 1.5 spec, sections 3.4.1 and 3.4.2).
//
// Which pixels: the quadrilateral of line_quad.cpp, walked by line_quad_walk.h. For width 1 this
// is the diamond-exit rule (with Mesa's treatment of the end pixels, see line_quad.cpp); for a
// wider non-antialiased line, with w the width rounded to an integer, a column of w fragments per
// x (x-major) or a row of w per y (y-major), as 3.4.2 asks.
//
// Attributes: t is measured along the major axis, t = (x_r - x_a) / (x_b - x_a) for an x-major
// segment (y for y-major). This is the interpolation 3.4.2 gives wide lines (every fragment of a
// column shares its values), used for every width as Mesa does; for width 1 it differs from
// equation 3.6's projection onto the segment by less than 1 / (2 |p_b - p_a|).
//   z = (1 - t) z_a + t z_b                                   (depth: linear in window space)
//   f = ((1 - t) f_a / w_a + t f_b / w_b) / ((1 - t) / w_a + t / w_b)   (varyings, eq. 3.6)
// t is not clamped to [0, 1]: the centre of an end fragment may lie beyond p_a or p_b along the
// major axis, and its values are then extrapolated, as equation 3.6 gives them and as Mesa does;
// colours are clamped later, depth when it is converted. Only where the extrapolation would make
// the perspective denominator zero or negative (a segment much shorter than a pixel between very
// different w) is t clamped.
//
// Stipple (3.4.1): a counter s advances by one for each fragment of a width-1 line (each column
// or row of a wide one); the fragment is kept when bit floor(s / factor) mod 16 of the pattern is
// set. The counter runs over fragments outside the bounds too: the scissor does not move it.
#include <algorithm>
#include <cmath>

#include "glass/raster/depth_value.h"
#include "glass/raster/line.h"
#include "glass/raster/line_run.h"
#include "line_quad.h"
#include "line_section.h"
#include "line_quad_walk.h"
#include "line_run_interpolation.h"
#include "subpixel.h"

namespace glass::raster {
namespace {

// Runs (line_run.h) in batches, with their attributes. Every fragment of a run (one column of an
// x-major line, one row of a y-major one) has the same t and so the same depth and varyings: they
// are computed once per run, for a whole batch at a time when it is handed on, the runs as lanes
// of vectors (line_run_interpolation.h).
class LineRunWriter {
 public:
  LineRunWriter(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
                bool xMajor, FragmentSink& sink)
      : sink_(sink), xMajor_(xMajor) {
    batch_.varyingCount = std::clamp(settings.varyingCount, 0, kMaxVaryings);
    batch_.alongX = !xMajor;
    ends_.start = xMajor ? a.x : a.y;
    ends_.length = (xMajor ? double(b.x) : double(b.y)) - ends_.start;
    ends_.qa = settings.perspectiveCorrect ? double(a.invW) : 1.0;
    ends_.qb = settings.perspectiveCorrect ? double(b.invW) : 1.0;
    ends_.za = a.z;
    ends_.zb = b.z;
    ends_.depthBias = settings.depthBias;
    ends_.varyingsA = a.varyings;
    ends_.varyingsB = b.varyings;
  }
  ~LineRunWriter() { flush(); }

  // The run at major coordinate `major`, minor coordinates minorFirst to minorLast; it must lie
  // within settings.bounds (the walk is clipped to them).
  void emit(int major, int minorFirst, int minorLast) {
    const int r = batch_.count++;
    majors_[r] = major;
    batch_.x[r] = xMajor_ ? major : minorFirst;
    batch_.y[r] = xMajor_ ? minorFirst : major;
    batch_.length[r] = minorLast - minorFirst + 1;
    if (batch_.count == LineRunBatch::kMaxRuns) flush();
  }

  void flush() {
    if (batch_.count == 0) return;
    // interpolateLineRuns reads whole vectors of majors, up to kLineRunLanes past the count.
    const int paddedCount = (batch_.count + kLineRunLanes - 1) / kLineRunLanes * kLineRunLanes;
    std::fill(majors_ + batch_.count, majors_ + paddedCount, 0);
    interpolateLineRuns(ends_, majors_, batch_);
    sink_.processLineRuns(batch_);
    batch_.count = 0;
  }

 private:
  FragmentSink& sink_;
  bool xMajor_;
  LineRunEnds ends_;
  int majors_[LineRunBatch::kMaxRuns];  // flush() sets those past the count that are read
  LineRunBatch batch_;
};

// Draws the fragments inside settings.bounds of the segment whose quad (lineQuadOf) is given.
// The stipple counter starts at stippleStart; when stippleEnd is set, it receives the counter
// after the whole segment.
void drawLine(const LineQuad& quad, const WindowVertex& a, const WindowVertex& b,
              const LineSettings& settings, int stippleStart, int* stippleEnd, FragmentSink& sink) {
  LineRunWriter writer(a, b, settings, quad.xMajor, sink);

  const PixelRect& r = settings.bounds;
  LineQuadClip clip;
  clip.majorLow = quad.xMajor ? r.x0 : r.y0;
  clip.majorHigh = int64_t{quad.xMajor ? r.x1 : r.y1} - 1;
  clip.minorLow = quad.xMajor ? r.y0 : r.x0;
  clip.minorHigh = int64_t{quad.xMajor ? r.y1 : r.x1} - 1;
  const bool increasing = quad.xMajor ? b.x > a.x : b.y > a.y;
  if (settings.stippleFactor <= 0) {
    walkLineQuad(quad, increasing, clip, RunCount::None,
                 [&](int major, int first, int last, int64_t) { writer.emit(major, first, last); });
    return;
  }
  // The counter steps once per run, inside the bounds or not, so the runs before the bounds are
  // counted (and those after them too when the caller wants the counter at the end).
  const int factor = settings.stippleFactor;
  const unsigned pattern = settings.stipplePattern;
  const int64_t runs = walkLineQuad(
      quad, increasing, clip, stippleEnd ? RunCount::All : RunCount::ThroughClip,
      [&](int major, int first, int last, int64_t run) {
        const int64_t counter = stippleStart + run;
        if ((pattern >> ((counter / factor) % 16)) & 1u) writer.emit(major, first, last);
      });
  if (stippleEnd) *stippleEnd = static_cast<int>(stippleStart + runs);
}

}  // namespace

bool lineQuadOf(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
                LineQuad& quad) {
  if (!isRasterizableCoordinate(a.x) || !isRasterizableCoordinate(a.y) ||
      !isRasterizableCoordinate(b.x) || !isRasterizableCoordinate(b.y))
    return false;
  return makeLineQuad(a.x, a.y, b.x, b.y, settings.width, settings.framebufferHeight, quad);
}

PixelRect lineQuadPixels(const LineQuad& quad, const PixelRect& bounds) {
  // Pixel (x, y) has its centre at (256 x, 256 y) in the quad's fixed point, and the walk takes
  // only centres inside the quad, so inside its corners' box.
  const int64_t x0 = *std::min_element(quad.x, quad.x + 4), x1 = *std::max_element(quad.x, quad.x + 4);
  const int64_t y0 = *std::min_element(quad.y, quad.y + 4), y1 = *std::max_element(quad.y, quad.y + 4);
  const int64_t left = std::max<int64_t>(line_quad_detail::ceilDiv(x0, 256), bounds.x0);
  const int64_t right = std::min<int64_t>(line_quad_detail::floorDiv(x1, 256) + 1, bounds.x1);
  const int64_t bottom = std::max<int64_t>(line_quad_detail::ceilDiv(y0, 256), bounds.y0);
  const int64_t top = std::min<int64_t>(line_quad_detail::floorDiv(y1, 256) + 1, bounds.y1);
  if (left >= right || bottom >= top) return PixelRect{};
  return PixelRect{static_cast<int>(left), static_cast<int>(bottom), static_cast<int>(right),
                   static_cast<int>(top)};
}

void rasterizeLine(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
                   FragmentSink& sink) {
  LineQuad quad;
  if (lineQuadOf(a, b, settings, quad)) rasterizeLine(quad, a, b, settings, sink);
}

void rasterizeLine(const LineQuad& quad, const WindowVertex& a, const WindowVertex& b,
                   const LineSettings& settings, FragmentSink& sink) {
  const bool counted = settings.stippleFactor > 0 && settings.stippleCounter != nullptr;
  drawLine(quad, a, b, settings, counted ? *settings.stippleCounter : 0,
           counted ? settings.stippleCounter : nullptr, sink);
}

void rasterizeLineSection(const LineQuad& quad, const WindowVertex& a, const WindowVertex& b,
                          const LineSettings& settings, int stippleStart, FragmentSink& sink) {
  drawLine(quad, a, b, settings, stippleStart, nullptr, sink);
}

}  // namespace glass::raster
