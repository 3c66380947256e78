#include "pixels/imaging_pipeline.h"

#include "pixels/color_matrix.h"
#include "pixels/color_tables.h"
#include "pixels/convolution.h"
#include "pixels/histogram_minmax.h"
#include "pixels/pixel_transfer.h"

namespace glass::gl {

namespace {

bool isIdentityScaleBias(const float scale[4], const float bias[4]) {
  for (int k = 0; k < 4; ++k) {
    if (scale[k] != 1.0f || bias[k] != 0.0f) return false;
  }
  return true;
}

// The convolution filter that applies to an image of the given dimensionality, or nullptr
// (a three-dimensional texture image has none).
const ConvolutionFilter* activeFilter(const ImagingState& s, int dimensions, int* target) {
  const ImagingPixelMode& m = s.mode;
  if (dimensions == 3) return nullptr;
  if (dimensions == 1) {
    *target = kConvolution1D;
  } else if (m.convolutionEnabled[kConvolution2D]) {
    *target = kConvolution2D;
  } else if (m.convolutionEnabled[kSeparable2D]) {
    *target = kSeparable2D;
  } else {
    return nullptr;
  }
  return m.convolutionEnabled[*target] ? &s.filters[*target] : nullptr;
}

// Everything after the earlier operations, before the final clamp.
bool applyImaging(ImagingState& s, RgbaImage& image, int dimensions) {
  const ImagingPixelMode& m = s.mode;
  if (m.colorTableEnabled[kColorTableStage]) {
    lookUpColorTable(s.tables[kColorTableStage], image.rgba.data(), image.count());
  }
  int target = 0;
  if (const ConvolutionFilter* filter = activeFilter(s, dimensions, &target)) {
    image = target == kSeparable2D ? convolve(separableAsFilter2D(*filter), m.convolution[target], image)
                                   : convolve(*filter, m.convolution[target], image);
  }
  const int count = image.count();
  float* rgba = image.rgba.data();
  if (!isIdentityScaleBias(m.postConvolutionScale, m.postConvolutionBias)) {
    for (int i = 0; i < count; ++i) {
      for (int k = 0; k < 4; ++k) {
        rgba[i * 4 + k] = rgba[i * 4 + k] * m.postConvolutionScale[k] + m.postConvolutionBias[k];
      }
    }
  }
  if (m.colorTableEnabled[kPostConvolutionStage]) {
    lookUpColorTable(s.tables[kPostConvolutionStage], rgba, count);
  }
  const Matrix4& matrix = s.colorMatrix.top();
  if (!colorMatrixIsIdentity(matrix, m.postColorMatrixScale, m.postColorMatrixBias)) {
    transformByColorMatrix(matrix, m.postColorMatrixScale, m.postColorMatrixBias, rgba, count);
  }
  if (m.colorTableEnabled[kPostColorMatrixStage]) {
    lookUpColorTable(s.tables[kPostColorMatrixStage], rgba, count);
  }
  if (m.histogramEnabled) {
    countInHistogram(s.histogram, rgba, count);
    if (s.histogram.sink) return false;
  }
  if (m.minmaxEnabled) {
    updateMinmax(s.minmax, rgba, count);
    if (s.minmax.sink) return false;
  }
  return true;
}

}  // namespace

bool imagingActive(const ImagingState& s) {
  const ImagingPixelMode& m = s.mode;
  for (bool enabled : m.colorTableEnabled) {
    if (enabled) return true;
  }
  for (bool enabled : m.convolutionEnabled) {
    if (enabled) return true;
  }
  return m.histogramEnabled || m.minmaxEnabled ||
         !isIdentityScaleBias(m.postConvolutionScale, m.postConvolutionBias) ||
         !colorMatrixIsIdentity(s.colorMatrix.top(), m.postColorMatrixScale, m.postColorMatrixBias);
}

bool transferColorImage(const PixelTransferState& transfer, ImagingState& imaging,
                        RgbaImage& image, int dimensions) {
  if (!imagingActive(imaging)) {
    transferColors(transfer, image.rgba.data(), image.count());
    return true;
  }
  scaleBiasAndMapColors(transfer, image.rgba.data(), image.count());
  if (!applyImaging(imaging, image, dimensions)) return false;
  clampColors(image.rgba.data(), image.count());
  return true;
}

bool transferConvertedColorImage(ImagingState& imaging, RgbaImage& image, int dimensions) {
  if (!imagingActive(imaging)) return true;
  if (!applyImaging(imaging, image, dimensions)) return false;
  clampColors(image.rgba.data(), image.count());
  return true;
}

}  // namespace glass::gl
