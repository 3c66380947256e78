#include "texture/mipmap_generation.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace glass::gl {
namespace {

// The weights by which the source texels of one axis contribute to each destination texel:
// destination texel i covers [i * n / m, (i + 1) * n / m) of the source axis (n source texels,
// m destination texels). Weights are in units of 1/m of a source texel, so they are integers:
// texel k, covering [k, k + 1), overlaps [i n / m, (i + 1) n / m) by
// (min((k + 1) m, (i + 1) n) - max(k m, i n)) / m.
struct AxisFootprint {
  int first;                 // the first source texel
  std::vector<int> weights;  // integer weights, summing to n
};

std::vector<AxisFootprint> axisFootprints(int n, int m) {
  std::vector<AxisFootprint> result(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    const long lo = static_cast<long>(i) * n, hi = static_cast<long>(i + 1) * n;
    AxisFootprint& f = result[static_cast<size_t>(i)];
    f.first = static_cast<int>(lo / m);
    for (int k = f.first; static_cast<long>(k) * m < hi; ++k) {
      const long overlap = std::min(static_cast<long>(k + 1) * m, hi) - std::max(static_cast<long>(k) * m, lo);
      f.weights.push_back(static_cast<int>(overlap));
    }
  }
  return result;
}

}  // namespace

TextureImage reduceImageByBoxFilter(const TextureImage& source) {
  TextureImage out;
  out.width = std::max(1, source.width / 2);
  out.height = std::max(1, source.height / 2);
  out.depth = std::max(1, source.depth / 2);
  out.border = source.border;
  out.internalFormat = source.internalFormat;
  out.base = source.base;
  out.depthBits = source.depthBits;
  if (source.isDepth()) out.depths.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height));
  out.texels.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) *
                    static_cast<size_t>(out.depth) * 4);

  const std::vector<AxisFootprint> fx = axisFootprints(source.width, out.width);
  const std::vector<AxisFootprint> fy = axisFootprints(source.height, out.height);
  const std::vector<AxisFootprint> fz = axisFootprints(source.depth, out.depth);
  // Total weight of a destination texel: n_x * n_y * n_z (each axis's weights sum to n).
  const long total = static_cast<long>(source.width) * static_cast<long>(source.height) *
                     static_cast<long>(source.depth);
  for (int k = 0; k < out.depth; ++k) {
    const AxisFootprint& rz = fz[static_cast<size_t>(k)];
    for (int j = 0; j < out.height; ++j) {
      const AxisFootprint& ry = fy[static_cast<size_t>(j)];
      for (int i = 0; i < out.width; ++i) {
        const AxisFootprint& rx = fx[static_cast<size_t>(i)];
        long sum[4] = {0, 0, 0, 0};
        double depthSum = 0.0;  // a depth image's values, weighted the same way
        for (size_t e = 0; e < rz.weights.size(); ++e) {
          for (size_t b = 0; b < ry.weights.size(); ++b) {
            for (size_t a = 0; a < rx.weights.size(); ++a) {
              const long w = static_cast<long>(rz.weights[e]) * ry.weights[b] * rx.weights[a];
              const uint8_t* t = source.texel(rx.first + static_cast<int>(a),
                                              ry.first + static_cast<int>(b),
                                              rz.first + static_cast<int>(e));
              for (int c = 0; c < 4; ++c) sum[c] += w * t[c];
              if (source.isDepth())
                depthSum += static_cast<double>(w) *
                            source.depths[source.texelIndex(rx.first + static_cast<int>(a),
                                                            ry.first + static_cast<int>(b), 0)];
            }
          }
        }
        uint8_t* d = out.texel(i, j, k);
        // Round to nearest, halves up: (sum + total / 2) / total.
        for (int c = 0; c < 4; ++c) d[c] = static_cast<uint8_t>((2 * sum[c] + total) / (2 * total));
        if (source.isDepth())
          out.depths[out.texelIndex(i, j, 0)] = static_cast<float>(depthSum / static_cast<double>(total));
      }
    }
  }
  return out;
}

void generateMipmaps(TextureObject& texture, int face) {
  const int base = texture.params.baseLevel;
  if (base < 0 || base >= kMaxTextureLevels || !texture.image(face, base).defined()) return;
  const TextureImage& b = texture.image(face, base);
  const int q =
      std::min(lastMipmapLevel(base, b.width, b.height, b.depth), texture.params.maxLevel);
  for (int level = base + 1; level <= q; ++level)
    texture.image(face, level) = reduceImageByBoxFilter(texture.image(face, level - 1));
  texture.updateCompleteness();
}

}  // namespace glass::gl
