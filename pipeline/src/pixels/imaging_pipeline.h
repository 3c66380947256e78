// The imaging subset's pixel transfer operations on RGBA groups (OpenGL 1.4 specification,
// section 3.6.5 and figure 3.7), after scale and bias and the GL_MAP_COLOR lookups and before the
// final clamp to [0, 1], in the specification's order:
//   colour table lookup (GL_COLOR_TABLE)
//   convolution (GL_CONVOLUTION_2D, or else GL_SEPARABLE_2D, for two-dimensional images;
//     GL_CONVOLUTION_1D for one-dimensional ones), then the post-convolution scale and bias
//   post-convolution colour table lookup (GL_POST_CONVOLUTION_COLOR_TABLE)
//   colour matrix, then the post-colour-matrix scale and bias
//   post-colour-matrix colour table lookup (GL_POST_COLOR_MATRIX_COLOR_TABLE)
//   histogram (GL_HISTOGRAM), whose sink discards the groups
//   minmax (GL_MINMAX), whose sink discards the groups
// The post-convolution scale and bias apply whether or not a convolution is enabled, as in Mesa.
// glDrawPixels, glCopyPixels and glReadPixels apply them, and the texture image commands
// (texture/texture_pixel_transfer.h).
#pragma once

#include "pixels/imaging_state.h"
#include "pixels/pixel_transfer_state.h"
#include "pixels/rgba_image.h"

namespace glass::gl {

// Whether any imaging operation would change a group or count it. When none would, the transfer
// operations are exactly those of pixel_transfer.h, at their cost.
bool imagingActive(const ImagingState& imaging);

// The colour transfer operations of a `dimensions`-dimensional image (1 or 2; 3 for the slices of
// a 3D texture image, which are not convolved): those of
// pixel_transfer.h with the imaging operations before the final clamp. Returns false when a sink
// discarded the groups (nothing is to be drawn or written). The image may shrink (convolution in
// GL_REDUCE mode) to nothing. Throws std::bad_alloc.
bool transferColorImage(const PixelTransferState& transfer, ImagingState& imaging,
                        RgbaImage& image, int dimensions);

// The imaging operations alone on groups already through the earlier operations and clamped
// (colour indices converted to RGBA, spec 3.6.5 "Color Index Lookup"), then clamped again.
bool transferConvertedColorImage(ImagingState& imaging, RgbaImage& image, int dimensions);

}  // namespace glass::gl
