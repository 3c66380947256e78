// Convolution (OpenGL 1.4 specification, section 3.6.5, "Convolution"): a one- or
// two-dimensional filter Cf of Wf x Hf elements applied to an image Cs.
//
//   GL_REDUCE:           C[i,j] = sum_n sum_m Cs[i+m, j+n] * Cf[m,n], the image shrinking to
//                        (Ws - Wf + 1) x (Hs - Hf + 1) (nothing left when that is not positive)
//   GL_CONSTANT_BORDER,  C[i,j] = sum_n sum_m Cs[i+m-Cw, j+n-Ch] * Cf[m,n], Cw = floor(Wf/2),
//   GL_REPLICATE_BORDER  Ch = floor(Hf/2), the image keeping its size; source groups outside the
//                        image are GL_CONVOLUTION_BORDER_COLOR (constant) or the nearest group of
//                        the image (replicate)
//
// The filter's internal format says which components are filtered (table 3.18): GL_ALPHA filters
// A; GL_LUMINANCE filters R, G and B by L; GL_LUMINANCE_ALPHA R, G, B by L and A by A;
// GL_INTENSITY all four by I; GL_RGB R, G, B; GL_RGBA all four. A component the filter does not
// name keeps the value of the source group under the filter's centre, Cs[i+Cw, j+Ch] in reduce
// mode and Cs[i,j] in the border modes. A separable filter is the outer product of its row and
// column filters, Cf[m,n] = Crow[m] * Ccol[n] per component.
#pragma once

#include "pixels/imaging_state.h"
#include "pixels/rgba_image.h"

namespace glass::gl {

// The filtered image; `filter` is a 1D (height 1) or 2D filter, `parameters` its border mode
// and colour. Sums run over n, then m, in float. Throws std::bad_alloc.
RgbaImage convolve(const ConvolutionFilter& filter, const ConvolutionParameters& parameters,
                   const RgbaImage& source);

// The 2D filter a separable filter stands for (its row and column filters multiplied).
ConvolutionFilter separableAsFilter2D(const ConvolutionFilter& separable);

}  // namespace glass::gl
