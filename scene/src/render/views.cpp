#include "render/views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "glass/geometry/teaching_scales.h"

namespace glass::scene {

Image imageFromGlRows(std::vector<std::uint8_t> rgba, int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba = std::move(rgba);
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
  for (int y = 0, other = height - 1; y < other; ++y, --other) {
    std::swap_ranges(&image.rgba[static_cast<std::size_t>(y) * rowBytes],
                     &image.rgba[static_cast<std::size_t>(y) * rowBytes] + rowBytes,
                     &image.rgba[static_cast<std::size_t>(other) * rowBytes]);
  }
  return image;
}

Image depthImage(const std::vector<float> &depth, int width, int height, std::string &notes) {
  float nearest = 1.0f, farthest = 0.0f;
  for (float d : depth) {
    if (d < 1.0f) {
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
    }
  }
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  bool any = nearest <= farthest;
  double span = any && farthest > nearest ? static_cast<double>(farthest) - nearest : 1.0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float d = depth[static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
      double grey = d >= 1.0f ? 1.0 : (static_cast<double>(d) - nearest) / span;
      auto level = static_cast<std::uint8_t>(std::lround(std::clamp(grey, 0.0, 1.0) * 255.0));
      std::uint8_t *p = &image.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4];
      p[0] = p[1] = p[2] = level;
      p[3] = 255;
    }
  }
  char buffer[160];
  if (any) {
    std::snprintf(buffer, sizeof buffer, "depth: drawn between %.6f (black) and %.6f (white); background 1 (white)",
                  static_cast<double>(nearest), static_cast<double>(farthest));
  } else {
    std::snprintf(buffer, sizeof buffer, "depth: nothing was drawn with depth below 1");
  }
  notes = buffer;
  return image;
}

std::array<std::uint8_t, 3> overdrawColor(int count) { return geometry::overdrawScaleColor(count); }

Image overdrawImage(const std::vector<std::uint8_t> &counts, int width, int height, std::string &notes) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  int largest = 0;
  std::uint64_t total = 0, covered = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      int count = counts[static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
      largest = std::max(largest, count);
      if (count > 0) {
        total += static_cast<std::uint64_t>(count);
        ++covered;
      }
      std::array<std::uint8_t, 3> c = overdrawColor(count);
      std::uint8_t *p = &image.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4];
      p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
    }
  }
  char buffer[200];
  std::snprintf(buffer, sizeof buffer,
                "overdraw: up to %d fragment%s in a pixel; %.2f on average over the %llu pixels drawn%s", largest,
                largest == 1 ? "" : "s", covered ? static_cast<double>(total) / static_cast<double>(covered) : 0.0,
                static_cast<unsigned long long>(covered), largest >= 255 ? " (255 is the stencil's limit)" : "");
  notes = buffer;
  return image;
}

Image boxDownsample(Image image, int factor) {
  if (factor <= 1) return image;
  Image out;
  out.width = image.width / factor;
  out.height = image.height / factor;
  out.rgba.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
  const unsigned samples = static_cast<unsigned>(factor * factor);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      unsigned sum[4] = {0, 0, 0, 0};
      for (int sy = 0; sy < factor; ++sy) {
        const std::uint8_t *row = &image.rgba[(static_cast<std::size_t>(y * factor + sy) * static_cast<std::size_t>(image.width) +
                                               static_cast<std::size_t>(x * factor)) * 4];
        for (int sx = 0; sx < factor; ++sx) {
          for (int c = 0; c < 4; ++c) sum[c] += row[sx * 4 + c];
        }
      }
      std::uint8_t *p = &out.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x)) * 4];
      for (int c = 0; c < 4; ++c) p[c] = static_cast<std::uint8_t>((sum[c] + samples / 2) / samples);
    }
  }
  return out;
}

} // namespace glass::scene
