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
#include <cstring>

#include "glass/raster/depth_value.h"
#include "glass/raster/line.h"
#include "glass/raster/line_run.h"
#include "line_quad.h"
#include "line_section.h"
#include "line_quad_walk.h"
#include "subpixel.h"

namespace glass::raster {
namespace {

// Runs (line_run.h) in batches, with their attributes. Every fragment of a run (one column of an
// x-major line, one row of a y-major one) has the same t and so the same depth and varyings: they
// are computed once per run.
class LineRunWriter {
 public:
  LineRunWriter(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
                bool xMajor, FragmentSink& sink)
      : a_(a), b_(b), settings_(settings), sink_(sink), xMajor_(xMajor) {
    varyingCount_ = std::clamp(settings.varyingCount, 0, kMaxVaryings);
    start_ = xMajor ? a.x : a.y;
    length_ = (xMajor ? double(b.x) : double(b.y)) - start_;
    qa_ = settings.perspectiveCorrect ? double(a.invW) : 1.0;
    qb_ = settings.perspectiveCorrect ? double(b.invW) : 1.0;
    // The ends' varyings as doubles, once per segment, in whole groups of four (zeros after the
    // last), so that each run's interpolation is a loop of fixed length the compiler vectorizes.
    lanes_ = (varyingCount_ + kGroup - 1) / kGroup * kGroup;
    for (int k = 0; k < lanes_; ++k) {
      varyingsA_[k] = k < varyingCount_ ? double(a.varyings[k]) : 0.0;
      varyingsB_[k] = k < varyingCount_ ? double(b.varyings[k]) : 0.0;
    }
  }
  ~LineRunWriter() { flush(); }

  // The run at major coordinate `major`, minor coordinates minorFirst to minorLast; it must lie
  // within settings.bounds (the walk is clipped to them).
  void emit(int major, int minorFirst, int minorLast) {
    LineRun& run = runs_[count_++];
    run.first.x = xMajor_ ? major : minorFirst;
    run.first.y = xMajor_ ? minorFirst : major;
    run.length = minorLast - minorFirst + 1;
    interpolate(major, run.first);
    if (count_ == LineRunBatch::kMaxRuns) flush();
  }

  void flush() {
    if (count_ == 0) return;
    LineRunBatch batch;
    batch.runs = runs_;
    batch.count = count_;
    batch.varyingCount = varyingCount_;
    batch.alongX = !xMajor_;
    sink_.processLineRuns(batch);
    count_ = 0;
  }

 private:
  // The depth and varyings at the centre of the runs at major coordinate `major`.
  void interpolate(int major, Fragment& f) const {
    const double centre = major + 0.5;
    double t = (centre - start_) / length_;
    // The weights of the two ends, (1 - t) q_a / q and t q_b / q, sum to one.
    double wa = (1.0 - t) * qa_, wb = t * qb_, q = wa + wb;
    if (!(q > 0.0)) {
      t = std::clamp(t, 0.0, 1.0);
      wa = (1.0 - t) * qa_, wb = t * qb_, q = wa + wb;
    }
    f.depth = depthValue((1.0 - t) * a_.z + t * b_.z + settings_.depthBias);
    // Without perspective (q_a = q_b = 1) q is (1 - t) + t, which is exactly 1 for almost every
    // t; w / 1 is w exactly (IEEE 754 division is correctly rounded), so the divisions are skipped
    // only where they cannot change a bit.
    const bool unit = q == 1.0;
    const double weightA = unit ? wa : wa / q, weightB = unit ? wb : wb / q;
    for (int group = 0; group < lanes_; group += kGroup) {
      float values[kGroup];
      for (int k = 0; k < kGroup; ++k)
        values[k] = static_cast<float>(weightA * varyingsA_[group + k] + weightB * varyingsB_[group + k]);
      std::memcpy(f.varyings + group, values, sizeof values);
    }
  }

  static constexpr int kGroup = 4;
  static_assert(kMaxVaryings % kGroup == 0);

  const WindowVertex& a_;
  const WindowVertex& b_;
  const LineSettings& settings_;
  FragmentSink& sink_;
  bool xMajor_;
  int varyingCount_;
  double start_, length_, qa_, qb_;
  int lanes_;  // varyingCount_ rounded up to whole groups
  double varyingsA_[kMaxVaryings], varyingsB_[kMaxVaryings];
  LineRun runs_[LineRunBatch::kMaxRuns];
  int count_ = 0;
};

// Draws the segment's fragments inside settings.bounds. The stipple counter starts at
// stippleStart; when stippleEnd is set, it receives the counter after the whole segment.
void drawLine(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
              int stippleStart, int* stippleEnd, FragmentSink& sink) {
  if (!isRasterizableCoordinate(a.x) || !isRasterizableCoordinate(a.y) ||
      !isRasterizableCoordinate(b.x) || !isRasterizableCoordinate(b.y))
    return;
  LineQuad quad;
  if (!makeLineQuad(a.x, a.y, b.x, b.y, settings.width, settings.framebufferHeight, quad)) return;
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

void rasterizeLine(const WindowVertex& a, const WindowVertex& b, const LineSettings& settings,
                   FragmentSink& sink) {
  const bool counted = settings.stippleFactor > 0 && settings.stippleCounter != nullptr;
  drawLine(a, b, settings, counted ? *settings.stippleCounter : 0,
           counted ? settings.stippleCounter : nullptr, sink);
}

void rasterizeLineSection(const WindowVertex& a, const WindowVertex& b,
                          const LineSettings& settings, int stippleStart, FragmentSink& sink) {
  drawLine(a, b, settings, stippleStart, nullptr, sink);
}

}  // namespace glass::raster
