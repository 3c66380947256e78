#include "pixels/histogram_minmax.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace glass::gl {

namespace {

// The components a histogram or minmax format names, by the RGBA component they come from
// (table 3.15: luminance is R). Histograms and minmax tables take no intensity format.
struct NamedComponents {
  bool named[4];
};

NamedComponents namedComponents(BaseFormat base) {
  switch (base) {
    case BaseFormat::Alpha: return {{false, false, false, true}};
    case BaseFormat::Luminance: return {{true, false, false, false}};
    case BaseFormat::LuminanceAlpha: return {{true, false, false, true}};
    case BaseFormat::RGB: return {{true, true, true, false}};
    case BaseFormat::Intensity:
    case BaseFormat::RGBA: break;
  }
  return {{true, true, true, true}};
}

int counterIndex(float c, int width) {
  if (std::isnan(c)) return 0;
  const long index = std::lround(std::clamp(c, 0.0f, 1.0f) * static_cast<float>(width - 1));
  return static_cast<int>(std::clamp<long>(index, 0, width - 1));
}

}  // namespace

void Minmax::reset() {
  for (int k = 0; k < 4; ++k) {
    minimum[k] = std::numeric_limits<float>::max();
    maximum[k] = std::numeric_limits<float>::lowest();
  }
}

void countInHistogram(Histogram& histogram, const float* rgba, int count) {
  if (histogram.width == 0) return;
  const NamedComponents named = namedComponents(histogram.base);
  for (int i = 0; i < count; ++i) {
    const float* c = rgba + static_cast<size_t>(i) * 4;
    for (int k = 0; k < 4; ++k) {
      if (!named.named[k]) continue;
      uint32_t& counter = histogram.counts[static_cast<size_t>(counterIndex(c[k], histogram.width)) * 4 + k];
      if (counter != std::numeric_limits<uint32_t>::max()) ++counter;  // saturates
    }
  }
}

void updateMinmax(Minmax& minmax, const float* rgba, int count) {
  const NamedComponents named = namedComponents(minmax.base);
  for (int i = 0; i < count; ++i) {
    const float* c = rgba + static_cast<size_t>(i) * 4;
    for (int k = 0; k < 4; ++k) {
      if (!named.named[k] || std::isnan(c[k])) continue;
      minmax.minimum[k] = std::min(minmax.minimum[k], c[k]);
      minmax.maximum[k] = std::max(minmax.maximum[k], c[k]);
    }
  }
}

}  // namespace glass::gl
