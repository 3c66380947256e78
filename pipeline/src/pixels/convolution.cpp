#include "pixels/convolution.h"

#include <algorithm>

namespace glass::gl {

namespace {

// Which components the filter's format filters (table 3.18), and from which of the stored
// filter components: luminance and intensity are kept in R (table 3.15).
struct FilteredComponents {
  bool filtered[4];
  int from[4];
};

FilteredComponents filteredComponents(BaseFormat base) {
  switch (base) {
    case BaseFormat::Alpha: return {{false, false, false, true}, {0, 1, 2, 3}};
    case BaseFormat::Luminance: return {{true, true, true, false}, {0, 0, 0, 3}};
    case BaseFormat::LuminanceAlpha: return {{true, true, true, true}, {0, 0, 0, 3}};
    case BaseFormat::Intensity: return {{true, true, true, true}, {0, 0, 0, 0}};
    case BaseFormat::RGB: return {{true, true, true, false}, {0, 1, 2, 3}};
    case BaseFormat::RGBA: break;
  }
  return {{true, true, true, true}, {0, 1, 2, 3}};
}

// The source group at (x, y), which may lie outside the image in the border modes.
const float* sourceGroup(const RgbaImage& source, const ConvolutionParameters& p, int x, int y) {
  if (x >= 0 && y >= 0 && x < source.width && y < source.height) return source.at(x, y);
  if (p.borderMode == GL_CONSTANT_BORDER) return p.borderColor;
  return source.at(std::clamp(x, 0, source.width - 1), std::clamp(y, 0, source.height - 1));
}

}  // namespace

RgbaImage convolve(const ConvolutionFilter& filter, const ConvolutionParameters& parameters,
                   const RgbaImage& source) {
  const bool reduce = parameters.borderMode == GL_REDUCE;
  const int wf = filter.width, hf = filter.height;
  if (wf == 0 || hf == 0) return source;  // no filter was specified: nothing to apply
  RgbaImage out;
  out.width = reduce ? std::max(source.width - wf + 1, 0) : source.width;
  out.height = reduce ? std::max(source.height - hf + 1, 0) : source.height;
  if (out.width == 0 || out.height == 0) {
    out.width = out.height = 0;
    return out;
  }
  out.rgba.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) * 4);
  // The offset from the output group to the source group under Cf[0,0].
  const int dx = reduce ? 0 : -(wf / 2), dy = reduce ? 0 : -(hf / 2);
  // The offset from the output group to the source group under the filter's centre.
  const int cx = reduce ? wf / 2 : 0, cy = reduce ? hf / 2 : 0;
  const FilteredComponents f = filteredComponents(filter.base);
  for (int j = 0; j < out.height; ++j) {
    for (int i = 0; i < out.width; ++i) {
      float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (int n = 0; n < hf; ++n) {
        for (int m = 0; m < wf; ++m) {
          const float* s = sourceGroup(source, parameters, i + m + dx, j + n + dy);
          const float* w = &filter.values[(static_cast<size_t>(n) * wf + m) * 4];
          for (int k = 0; k < 4; ++k) sum[k] += s[k] * w[f.from[k]];
        }
      }
      const float* centre = sourceGroup(source, parameters, i + cx, j + cy);
      float* o = out.at(i, j);
      for (int k = 0; k < 4; ++k) o[k] = f.filtered[k] ? sum[k] : centre[k];
    }
  }
  return out;
}

ConvolutionFilter separableAsFilter2D(const ConvolutionFilter& separable) {
  ConvolutionFilter f = separable;  // format and size; the values are replaced
  f.values.resize(static_cast<size_t>(f.width) * static_cast<size_t>(f.height) * 4);
  const float* row = separable.values.data();
  const float* column = row + static_cast<size_t>(f.width) * 4;
  for (int n = 0; n < f.height; ++n) {
    for (int m = 0; m < f.width; ++m) {
      for (int k = 0; k < 4; ++k) {
        f.values[(static_cast<size_t>(n) * f.width + m) * 4 + k] = row[m * 4 + k] * column[n * 4 + k];
      }
    }
  }
  return f;
}

}  // namespace glass::gl
