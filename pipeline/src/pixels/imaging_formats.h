// The internal formats of colour tables, convolution filters, histograms and minmax tables
// (OpenGL 1.4 specification, section 3.6.3 and table 3.15), and how their entries are kept.
#pragma once

#include <GL/gl.h>

#include "texture/texture_image.h"

namespace glass::gl {

// The base format of an internal format of table 3.15 (GL_ALPHA, GL_LUMINANCE4, ..., GL_RGBA16).
// False for anything else, the component counts 1 to 4 and the compressed formats included:
// the imaging commands take only the names of table 3.15 (GL_INVALID_ENUM otherwise).
bool imagingBaseFormat(GLenum internalFormat, BaseFormat* base);

// Keeps the components of an RGBA group that `base` holds (table 3.15: luminance and intensity
// are R) and sets the others as glGetColorTable and glGetConvolutionFilter return them (table
// 6.1: missing R, G, B are 0 and a missing A is 1), so that the stored entry is the returned one.
void keepBaseComponents(BaseFormat base, float* rgba);

// Bits per component as the GL_COLOR_TABLE_RED_SIZE ... GL_COLOR_TABLE_INTENSITY_SIZE and
// GL_HISTOGRAM_RED_SIZE ... GL_HISTOGRAM_LUMINANCE_SIZE queries report them: `index` 0 to 5 for
// red, green, blue, alpha, luminance, intensity. Tables keep floats; glass reports 8 bits per
// component the format has, as for textures.
int imagingComponentBits(BaseFormat base, int index);

}  // namespace glass::gl
