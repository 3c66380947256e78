// The pixel transfer operations (OpenGL 1.5 specification, section 3.6.5, figure 3.7), applied to
// unpacked pixel rectangles by glDrawPixels and glCopyPixels, and to what glReadPixels reads
// (section 4.3.2), in the specification's order:
//   RGBA components:  scale and bias (GL_c_SCALE, GL_c_BIAS), then with GL_MAP_COLOR the
//                     GL_PIXEL_MAP_c_TO_c lookups, then clamping to [0, 1]
//   colour indices:   shift and offset (GL_INDEX_SHIFT, GL_INDEX_OFFSET), then to RGBA through
//                     the GL_PIXEL_MAP_I_TO_R/G/B/A maps (glass is an RGBA context)
//   stencil indices:  shift and offset, then with GL_MAP_STENCIL the GL_PIXEL_MAP_S_TO_S lookup
//                     (with the imaging subset, pixels/imaging_pipeline.h, its operations come
//                     before the clamp)
//   depth:            scale and bias (GL_DEPTH_SCALE, GL_DEPTH_BIAS), then clamping to [0, 1]
#pragma once

#include <cstdint>

#include "pixels/pixel_transfer_state.h"

namespace glass::gl {

// Whether scale and bias and the GL_MAP_COLOR lookups leave every RGBA group as it is (apart
// from the final clamp).
bool colorTransferChangesNothing(const PixelTransferState& t);

// count RGBA pixels (4 floats each), in place.
void transferColors(const PixelTransferState& t, float* rgba, int count);
// The same without the final clamp, for the imaging operations that come between
// (pixels/imaging_pipeline.h), and the clamp that then ends them.
void scaleBiasAndMapColors(const PixelTransferState& t, float* rgba, int count);
void clampColors(float* rgba, int count);
// count depth values, in place.
void transferDepths(const PixelTransferState& t, float* depth, int count);
// count stencil indices, in place.
void transferStencilIndices(const PixelTransferState& t, int32_t* indices, int count);
// count colour indices to RGBA (4 floats each).
void colorIndicesToRGBA(const PixelTransferState& t, const int32_t* indices, int count, float* rgba);

// Index shift and offset (spec 3.6.5, "Arithmetic on indices"): shifted left by GL_INDEX_SHIFT
// bits (right for a negative shift), then GL_INDEX_OFFSET added.
int32_t shiftAndOffsetIndex(const PixelTransferState& t, int32_t index);

}  // namespace glass::gl
