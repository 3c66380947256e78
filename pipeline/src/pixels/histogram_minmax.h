// Histogram and minmax (OpenGL 1.4 specification, section 3.6.5, "Histogram" and "Minmax"), the
// last of the pixel transfer operations on RGBA groups.
#pragma once

#include "pixels/imaging_state.h"

namespace glass::gl {

// Histogram: each component the histogram's format names (R, G, B, A; luminance counts R's
// value) selects counter round(clamp(c, 0, 1) * (width - 1)) of its component, which is
// incremented. A histogram of width 0 counts nothing.
void countInHistogram(Histogram& histogram, const float* rgba, int count);

// Minmax: each component the table's format names (luminance is R) lowers its minimum and raises
// its maximum. The values are those of the groups, not clamped.
void updateMinmax(Minmax& minmax, const float* rgba, int count);

}  // namespace glass::gl
