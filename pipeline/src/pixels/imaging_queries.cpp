#include "pixels/imaging_queries.h"

#include "core/context.h"
#include "core/state_value.h"

namespace glass::gl {

bool* imagingCapability(ImagingState& imaging, GLenum cap) {
  ImagingPixelMode& m = imaging.mode;
  switch (cap) {
    case GL_COLOR_TABLE: return &m.colorTableEnabled[kColorTableStage];
    case GL_POST_CONVOLUTION_COLOR_TABLE: return &m.colorTableEnabled[kPostConvolutionStage];
    case GL_POST_COLOR_MATRIX_COLOR_TABLE: return &m.colorTableEnabled[kPostColorMatrixStage];
    case GL_CONVOLUTION_1D: return &m.convolutionEnabled[kConvolution1D];
    case GL_CONVOLUTION_2D: return &m.convolutionEnabled[kConvolution2D];
    case GL_SEPARABLE_2D: return &m.convolutionEnabled[kSeparable2D];
    case GL_HISTOGRAM: return &m.histogramEnabled;
    case GL_MINMAX: return &m.minmaxEnabled;
    default: return nullptr;
  }
}

float* imagingTransferParameter(ImagingState& imaging, GLenum pname) {
  ImagingPixelMode& m = imaging.mode;
  if (pname >= GL_POST_CONVOLUTION_RED_SCALE && pname <= GL_POST_CONVOLUTION_ALPHA_SCALE) {
    return &m.postConvolutionScale[pname - GL_POST_CONVOLUTION_RED_SCALE];
  }
  if (pname >= GL_POST_CONVOLUTION_RED_BIAS && pname <= GL_POST_CONVOLUTION_ALPHA_BIAS) {
    return &m.postConvolutionBias[pname - GL_POST_CONVOLUTION_RED_BIAS];
  }
  if (pname >= GL_POST_COLOR_MATRIX_RED_SCALE && pname <= GL_POST_COLOR_MATRIX_ALPHA_SCALE) {
    return &m.postColorMatrixScale[pname - GL_POST_COLOR_MATRIX_RED_SCALE];
  }
  if (pname >= GL_POST_COLOR_MATRIX_RED_BIAS && pname <= GL_POST_COLOR_MATRIX_ALPHA_BIAS) {
    return &m.postColorMatrixBias[pname - GL_POST_COLOR_MATRIX_RED_BIAS];
  }
  return nullptr;
}

bool queryImagingState(const Context& ctx, GLenum pname, StateValue& v) {
  // Only read through the pointer.
  ImagingState& imaging = const_cast<Context&>(ctx).imaging;
  const float* value = imagingTransferParameter(imaging, pname);
  if (value) v.setFloats({*value});
  return value != nullptr;
}

}  // namespace glass::gl
