#include "pixels/color_tables.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace glass::gl {

namespace {

// The entry a component selects (spec 3.6.5): round(clamp(c, 0, 1) * (width - 1)).
int entryIndex(float c, int width) {
  const float clamped = std::clamp(c, 0.0f, 1.0f);  // NaN stays NaN and is caught below
  const long index = std::lround(clamped * static_cast<float>(width - 1));
  return static_cast<int>(std::clamp<long>(std::isnan(clamped) ? 0 : index, 0, width - 1));
}

}  // namespace

void lookUpColorTable(const ColorTable& table, float* rgba, int count) {
  if (table.width == 0) return;
  const float* entries = table.entries.data();
  const int w = table.width;
  // The component of a stored entry that holds luminance or intensity (table 3.15: R).
  auto entry = [&](float c, int component) { return entries[entryIndex(c, w) * 4 + component]; };
  for (int i = 0; i < count; ++i) {
    float* c = rgba + static_cast<size_t>(i) * 4;
    switch (table.base) {
      case BaseFormat::Alpha: c[3] = entry(c[3], 3); break;
      case BaseFormat::Luminance:
        for (int k = 0; k < 3; ++k) c[k] = entry(c[k], 0);
        break;
      case BaseFormat::LuminanceAlpha:
        for (int k = 0; k < 3; ++k) c[k] = entry(c[k], 0);
        c[3] = entry(c[3], 3);
        break;
      case BaseFormat::Intensity:
        for (int k = 0; k < 4; ++k) c[k] = entry(c[k], 0);
        break;
      case BaseFormat::RGB:
        for (int k = 0; k < 3; ++k) c[k] = entry(c[k], k);
        break;
      case BaseFormat::RGBA:
        for (int k = 0; k < 4; ++k) c[k] = entry(c[k], k);
        break;
    }
  }
}

}  // namespace glass::gl
