// Snapping window coordinates to the 1/256 pixel grid (rasterizer/src/subpixel.h): the rounding by
// adding and subtracting 1.5 * 2^52 must give std::nearbyint's result (ties to even) for every
// coordinate the rasterizers accept.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "subpixel.h"

using namespace glass::raster;

namespace {

int64_t referenceSnap(float v) {
  return static_cast<int64_t>(std::nearbyint(static_cast<double>(v) * double(kSubpixelOne)));
}

}  // namespace

TEST_CASE("snapping to the subpixel grid rounds as nearbyint does, ties to even") {
  const float limit = static_cast<float>(kMaxWindowCoordinate);
  // Ties (k + 1/2) / 256 and their neighbours one float step away, both signs, small and large.
  int checked = 0;
  for (const int64_t k : {int64_t{0}, int64_t{1}, int64_t{2}, int64_t{3}, int64_t{255}, int64_t{256}, int64_t{1000001},
                          int64_t{(int64_t{1} << 26) - 1}, int64_t{(int64_t{1} << 27) - 3}}) {
    for (const double sign : {1.0, -1.0}) {
      const float tie = static_cast<float>(sign * (static_cast<double>(k) + 0.5) / 256.0);
      if (static_cast<double>(tie) * 256.0 != sign * (static_cast<double>(k) + 0.5)) continue;  // not a float
      for (const float v : {tie, std::nextafter(tie, 0.0f), std::nextafter(tie, 2.0f * tie)}) {
        CAPTURE(v);
        CHECK(snapToSubpixel(v) == referenceSnap(v));
        ++checked;
      }
    }
  }
  CHECK(checked > 30);
  CHECK(snapToSubpixel(0.5f / 256.0f) == 0);    // 0.5 -> 0
  CHECK(snapToSubpixel(1.5f / 256.0f) == 2);    // 1.5 -> 2
  CHECK(snapToSubpixel(-2.5f / 256.0f) == -2);  // -2.5 -> -2
  for (const float v : {0.0f, -0.0f, limit, -limit, std::nextafter(limit, 0.0f), -std::nextafter(limit, 0.0f), 1e-30f, -1e-30f})
    CHECK(snapToSubpixel(v) == referenceSnap(v));
  // Random coordinates over the whole range and near the window.
  std::mt19937 random(5);
  std::uniform_real_distribution<float> wide(-limit, limit), near(-4.0f, 2000.0f);
  for (int i = 0; i < 200000; ++i) {
    const float v = i % 2 == 0 ? wide(random) : near(random);
    if (snapToSubpixel(v) != referenceSnap(v)) {
      CAPTURE(v);
      CHECK(snapToSubpixel(v) == referenceSnap(v));
    }
  }
}
