// The imaging subset's state (OpenGL 1.4 specification, section 3.6.3 and 3.6.5, GL_ARB_imaging;
// tables 6.18-6.22): the three colour tables and their proxies, the three convolution filters,
// the colour matrix stack, the post-convolution and post-colour-matrix scales and biases, the
// histogram and the minmax table.
//
// What glPushAttrib(GL_PIXEL_MODE_BIT) saves is gathered in ImagingPixelMode: the enables, the
// colour table scales and biases, the convolution parameters and the two scale and bias pairs.
// The tables, filters, histogram counts and minmax values belong to no attribute group.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "core/matrix_stack.h"
#include "texture/texture_image.h"

namespace glass::gl {

// The largest colour table and histogram (a power of two; widths above it are
// GL_TABLE_TOO_LARGE), and GL_MAX_CONVOLUTION_WIDTH/HEIGHT, as in Mesa.
inline constexpr int kMaxColorTableWidth = 256;
inline constexpr int kMaxHistogramWidth = 256;
inline constexpr int kMaxConvolutionSize = 9;
// GL_MAX_COLOR_MATRIX_STACK_DEPTH, as in Mesa (the specification asks for at least 2).
inline constexpr int kColorMatrixStackDepth = 4;

// The three colour tables in the order of the pipeline (spec figure 3.7).
enum ColorTableStage { kColorTableStage = 0, kPostConvolutionStage = 1, kPostColorMatrixStage = 2 };
inline constexpr int kColorTableStages = 3;

// The three convolution filters.
enum ConvolutionTarget { kConvolution1D = 0, kConvolution2D = 1, kSeparable2D = 2 };
inline constexpr int kConvolutionTargets = 3;

// A colour table (spec 3.6.3, "Color Table Specification"): width entries of RGBA floats in
// [0, 1], already scaled, biased and clamped; only the components of the internal format's
// base format are meaningful (table 3.15: luminance and intensity are kept in R).
struct ColorTable {
  GLenum internalFormat = GL_RGBA;
  BaseFormat base = BaseFormat::RGBA;
  int width = 0;
  std::vector<float> entries;  // 4 floats per entry
};

// A convolution filter (spec 3.6.3, "Convolution Filter Specification"): RGBA floats, scaled and
// biased but not clamped. A separable filter keeps its row (width entries) and column (height
// entries) filters one after the other in `values`.
struct ConvolutionFilter {
  GLenum internalFormat = GL_RGBA;
  BaseFormat base = BaseFormat::RGBA;
  int width = 0, height = 0;
  std::vector<float> values;  // 4 floats per element
};

struct ConvolutionParameters {
  GLenum borderMode = GL_REDUCE;                    // GL_CONVOLUTION_BORDER_MODE
  float borderColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // GL_CONVOLUTION_BORDER_COLOR
  float filterScale[4] = {1.0f, 1.0f, 1.0f, 1.0f};  // GL_CONVOLUTION_FILTER_SCALE
  float filterBias[4] = {0.0f, 0.0f, 0.0f, 0.0f};   // GL_CONVOLUTION_FILTER_BIAS
};

struct ImagingPixelMode {
  bool colorTableEnabled[kColorTableStages] = {};  // GL_COLOR_TABLE, GL_POST_..._COLOR_TABLE
  float colorTableScale[kColorTableStages][4] = {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}};
  float colorTableBias[kColorTableStages][4] = {};
  bool convolutionEnabled[kConvolutionTargets] = {};  // GL_CONVOLUTION_1D/2D, GL_SEPARABLE_2D
  ConvolutionParameters convolution[kConvolutionTargets];
  float postConvolutionScale[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  float postConvolutionBias[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  float postColorMatrixScale[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  float postColorMatrixBias[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  bool histogramEnabled = false;  // GL_HISTOGRAM
  bool minmaxEnabled = false;     // GL_MINMAX
};

// The histogram (spec 3.6.5, "Histogram"): width counters per component.
struct Histogram {
  int width = 0;
  GLenum internalFormat = GL_RGBA;
  BaseFormat base = BaseFormat::RGBA;
  bool sink = false;
  std::vector<uint32_t> counts;  // 4 per entry, RGBA (luminance counts in R)
};

// The minmax table (spec 3.6.5, "Minmax"): the least and greatest value of each component seen
// since the last reset; a reset sets them to the largest and smallest representable values.
struct Minmax {
  GLenum internalFormat = GL_RGBA;
  BaseFormat base = BaseFormat::RGBA;
  bool sink = false;
  float minimum[4];
  float maximum[4];
  Minmax() { reset(); }
  void reset();
};

struct ImagingState {
  ImagingPixelMode mode;
  ColorTable tables[kColorTableStages];
  ColorTable proxyTables[kColorTableStages];  // GL_PROXY_COLOR_TABLE, ...: size and format only
  ConvolutionFilter filters[kConvolutionTargets];
  MatrixStack colorMatrix{kColorMatrixStackDepth};
  Histogram histogram;
  Histogram proxyHistogram;  // GL_PROXY_HISTOGRAM: size and format only
  Minmax minmax;
};

}  // namespace glass::gl
