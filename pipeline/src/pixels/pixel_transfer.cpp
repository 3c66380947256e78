#include "pixels/pixel_transfer.h"

#include <algorithm>
#include <cmath>

namespace glass::gl {

namespace {

float clamp01(float c) { return std::clamp(c, 0.0f, 1.0f); }

// Spec 3.6.5, "RGBA to RGBA lookup": a component c in [0, 1] (clamped first) selects entry
// round(c * (size - 1)) of its map.
float lookUpColor(const std::vector<float>& map, float c) {
  const float last = static_cast<float>(map.size() - 1);
  const auto i = static_cast<size_t>(std::lround(clamp01(c) * last));
  return map[std::min(i, map.size() - 1)];
}

// Spec 3.6.5, "Color index lookup" and "Stencil index lookup": an index selects entry
// index mod size (sizes of index maps are powers of two).
float lookUpIndex(const std::vector<float>& map, int32_t index) {
  return map[static_cast<size_t>(static_cast<uint32_t>(index) & (map.size() - 1))];
}

}  // namespace

namespace {

bool scalesOrBiases(const PixelTransferState& t) {
  return t.scale[0] != 1.0f || t.scale[1] != 1.0f || t.scale[2] != 1.0f || t.scale[3] != 1.0f ||
         t.bias[0] != 0.0f || t.bias[1] != 0.0f || t.bias[2] != 0.0f || t.bias[3] != 0.0f;
}

// Scale and bias, then with GL_MAP_COLOR the lookups; the final clamp when asked.
void scaleBiasAndMap(const PixelTransferState& t, float* rgba, int count, bool clamp) {
  const bool scaleBias = scalesOrBiases(t);
  for (int i = 0; i < count; ++i) {
    float* c = rgba + static_cast<size_t>(i) * 4;
    if (scaleBias) {
      for (int k = 0; k < 4; ++k) c[k] = c[k] * t.scale[k] + t.bias[k];
    }
    if (t.mapColor) {
      for (int k = 0; k < 4; ++k) c[k] = lookUpColor(t.map(GL_PIXEL_MAP_R_TO_R + k), c[k]);
    }
    if (clamp) {
      for (int k = 0; k < 4; ++k) c[k] = clamp01(c[k]);
    }
  }
}

}  // namespace

bool colorTransferChangesNothing(const PixelTransferState& t) {
  return !scalesOrBiases(t) && !t.mapColor;
}

void transferColors(const PixelTransferState& t, float* rgba, int count) {
  scaleBiasAndMap(t, rgba, count, true);
}

void scaleBiasAndMapColors(const PixelTransferState& t, float* rgba, int count) {
  scaleBiasAndMap(t, rgba, count, false);
}

void clampColors(float* rgba, int count) {
  for (size_t i = 0; i < static_cast<size_t>(count) * 4; ++i) rgba[i] = clamp01(rgba[i]);
}

void transferDepths(const PixelTransferState& t, float* depth, int count) {
  for (int i = 0; i < count; ++i) depth[i] = clamp01(depth[i] * t.depthScale + t.depthBias);
}

int32_t shiftAndOffsetIndex(const PixelTransferState& t, int32_t index) {
  // In 64 bits so that large shifts and offsets wrap the way the final masking expects.
  int64_t value = index;
  if (t.indexShift > 0) {
    value = t.indexShift >= 32 ? 0 : static_cast<int64_t>(static_cast<uint64_t>(value) << t.indexShift);
  } else if (t.indexShift < 0) {
    value = t.indexShift <= -32 ? (value < 0 ? -1 : 0) : value >> -t.indexShift;
  }
  return static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(value + t.indexOffset)));
}

void transferStencilIndices(const PixelTransferState& t, int32_t* indices, int count) {
  for (int i = 0; i < count; ++i) {
    int32_t index = shiftAndOffsetIndex(t, indices[i]);
    if (t.mapStencil) index = static_cast<int32_t>(lookUpIndex(t.map(GL_PIXEL_MAP_S_TO_S), index));
    indices[i] = index;
  }
}

void colorIndicesToRGBA(const PixelTransferState& t, const int32_t* indices, int count, float* rgba) {
  for (int i = 0; i < count; ++i) {
    const int32_t index = shiftAndOffsetIndex(t, indices[i]);
    float* c = rgba + static_cast<size_t>(i) * 4;
    for (int k = 0; k < 4; ++k) c[k] = clamp01(lookUpIndex(t.map(GL_PIXEL_MAP_I_TO_R + k), index));
  }
}

}  // namespace glass::gl
