// GL line segments drawn tile by tile (TiledRasterizer) against the same segments walked whole.
//
// The tiled rasterizer draws a segment once per 64 x 64 tile it touches, walking only the runs
// inside the tile and starting its stipple counter from the runs before them. Here random
// segments (every octant, sub-pixel and arbitrary float endpoints, partly outside the window,
// widths 1 to 7, stippled or not, perspective-correct or not) are drawn that way and, as the
// reference, by rasterizeLine with bounds that hold the whole segment, so that every run is
// walked; the reference's fragments inside the window (or a scissor box) must be exactly the
// tiled fragments: same pixels, same depth bits, same varying bits, and the same stipple counter
// after each segment. The reference's attributes are also checked against the interpolation of
// line.cpp evaluated per fragment (t and both weights by division, spec 3.4.2 and equation 3.6).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <tuple>
#include <vector>

#include "glass/raster/depth_value.h"
#include "glass/raster/framebuffer.h"
#include "glass/raster/line.h"
#include "glass/raster/tiled_rasterizer.h"
#include "raster_test_support.h"

using namespace glass::raster;
using glass::raster::test::RecordingSink;

namespace {

constexpr int kWidth = 300, kHeight = 200;

bool samePixel(const Fragment& f, const Fragment& g) { return f.x == g.x && f.y == g.y; }
bool sameBits(const Fragment& f, const Fragment& g, int varyingCount) {
  return samePixel(f, g) && f.depth == g.depth &&
         std::memcmp(f.varyings, g.varyings, sizeof(float) * static_cast<size_t>(varyingCount)) == 0;
}
std::vector<Fragment> sortedByPixel(std::vector<Fragment> fragments) {
  std::sort(fragments.begin(), fragments.end(), [](const Fragment& f, const Fragment& g) {
    return std::tie(f.x, f.y) < std::tie(g.x, g.y);
  });
  return fragments;
}

// The attributes of the fragment at (x, y), each by its own divisions: the interpolation of
// line.cpp written out per fragment.
Fragment interpolatedPerFragment(int x, int y, const WindowVertex& a, const WindowVertex& b,
                                 const LineSettings& s, bool xMajor) {
  const double start = xMajor ? a.x : a.y;
  const double length = (xMajor ? double(b.x) : double(b.y)) - start;
  const double qa = s.perspectiveCorrect ? double(a.invW) : 1.0;
  const double qb = s.perspectiveCorrect ? double(b.invW) : 1.0;
  double t = ((xMajor ? x : y) + 0.5 - start) / length;
  double wa = (1.0 - t) * qa, wb = t * qb, q = wa + wb;
  if (!(q > 0.0)) {
    t = std::clamp(t, 0.0, 1.0);
    wa = (1.0 - t) * qa, wb = t * qb, q = wa + wb;
  }
  Fragment f{};
  f.x = x;
  f.y = y;
  f.depth = depthValue((1.0 - t) * a.z + t * b.z + s.depthBias);
  for (int k = 0; k < s.varyingCount; ++k)
    f.varyings[k] = static_cast<float>(wa / q * a.varyings[k] + wb / q * b.varyings[k]);
  return f;
}

class RandomLines {
 public:
  explicit RandomLines(unsigned seed) : rng_(seed) {}

  float coordinate(float low, float high) {
    const float v = std::uniform_real_distribution<float>(low, high)(rng_);
    switch (pick(5)) {  // pixel borders, centres, quarter and 1/256 grids, arbitrary floats
      case 0: return std::floor(v);
      case 1: return std::floor(v) + 0.5f;
      case 2: return std::floor(v * 4.0f) / 4.0f;
      case 3: return std::floor(v * 256.0f) / 256.0f;
      default: return v;
    }
  }
  WindowVertex vertex(int varyingCount) {
    WindowVertex v{};
    v.x = coordinate(-40.0f, kWidth + 40.0f);
    v.y = coordinate(-40.0f, kHeight + 40.0f);
    v.z = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng_);
    v.invW = std::uniform_real_distribution<float>(0.1f, 4.0f)(rng_);
    for (int k = 0; k < varyingCount; ++k)
      v.varyings[k] = std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng_);
    return v;
  }
  // Short segments too: most of a frame's lines are a few pixels long.
  WindowVertex near(const WindowVertex& a, int varyingCount) {
    WindowVertex v = vertex(varyingCount);
    v.x = a.x + coordinate(-12.0f, 12.0f);
    v.y = a.y + coordinate(-12.0f, 12.0f);
    return v;
  }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

 private:
  std::mt19937 rng_;
};

// With one thread a segment within a tile's size is drawn at once and a longer one binned; with
// two, every segment is binned, to the tiles its quad's pixels reach.
void checkLinesDrawnTileByTile(int threads) {
  CAPTURE(threads);
  Framebuffer framebuffer(kWidth, kHeight);
  TiledRasterizer tiled(framebuffer, threads);
  RandomLines random(12345);
  const PixelRect window{0, 0, kWidth, kHeight};
  const PixelRect scissor{37, 23, 251, 177};
  const PixelRect everywhere{-4096, -4096, 4096, 4096};
  const float widths[] = {1, 1, 1, 1, 2, 3, 4, 7};
  int fragmentsCompared = 0, stippledSegments = 0, wideSegments = 0;
  for (int i = 0; i < 4000; ++i) {
    LineSettings s;
    s.varyingCount = random.pick(5);
    s.width = widths[random.pick(8)];
    s.perspectiveCorrect = random.pick(2) == 0;
    s.depthBias = random.pick(4) == 0 ? 1.0 / 1024 : 0.0;
    s.framebufferHeight = kHeight;
    int counterWhole = 0, counterTiled = 0;
    if (random.pick(3) == 0) {
      s.stippleFactor = 1 + random.pick(4);
      s.stipplePattern = static_cast<unsigned short>(random.pick(65536));
      counterWhole = counterTiled = random.pick(200);
      ++stippledSegments;
    }
    if (s.width > 1) ++wideSegments;
    const WindowVertex a = random.vertex(s.varyingCount);
    const WindowVertex b = random.pick(2) == 0 ? random.near(a, s.varyingCount)
                                               : random.vertex(s.varyingCount);
    const PixelRect bounds = random.pick(4) == 0 ? scissor : window;
    CAPTURE(i);
    CAPTURE(a.x);
    CAPTURE(a.y);
    CAPTURE(b.x);
    CAPTURE(b.y);
    CAPTURE(s.width);
    CAPTURE(s.stippleFactor);

    LineSettings whole = s;
    whole.bounds = everywhere;
    whole.stippleCounter = &counterWhole;
    RecordingSink wholeSink;
    rasterizeLine(a, b, whole, wholeSink);

    LineSettings perTile = s;
    perTile.bounds = bounds;
    perTile.stippleCounter = &counterTiled;
    RecordingSink tiledSink;
    tiled.line(a, b, perTile, tiledSink);
    tiled.finish();
    CHECK(counterTiled == counterWhole);

    // Major axis as makeLineQuad finds it, on rows numbered down from the top (line_quad.cpp).
    const float top = static_cast<float>(kHeight);
    const float dx = std::fabs(a.x - b.x), dy = std::fabs((top - a.y) - (top - b.y));
    std::vector<Fragment> expected;
    for (const Fragment& f : wholeSink.fragments) {
      const Fragment reference = interpolatedPerFragment(f.x, f.y, a, b, s, dx >= dy);
      REQUIRE(sameBits(f, reference, s.varyingCount));
      if (f.x >= bounds.x0 && f.x < bounds.x1 && f.y >= bounds.y0 && f.y < bounds.y1)
        expected.push_back(f);
    }
    const std::vector<Fragment> got = sortedByPixel(tiledSink.fragments);
    expected = sortedByPixel(expected);
    REQUIRE(got.size() == expected.size());
    for (size_t k = 0; k < got.size(); ++k) REQUIRE(sameBits(got[k], expected[k], s.varyingCount));
    fragmentsCompared += static_cast<int>(got.size());
  }
  // The sample is not degenerate: many fragments, stippled and wide segments among them.
  CHECK(fragmentsCompared > 100000);
  CHECK(stippledSegments > 1000);
  CHECK(wideSegments > 1000);
}

}  // namespace

TEST_CASE("GL lines drawn tile by tile give the fragments of the whole segment, bit for bit") {
  checkLinesDrawnTileByTile(1);
  checkLinesDrawnTileByTile(2);
}
