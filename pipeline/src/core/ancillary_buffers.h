// Which ancillary buffers a context's framebuffer has. OpenGL 1.5, chapter 4: a framebuffer may
// lack a depth, stencil or accumulation buffer (an OSMesa context asks for each by its bits; one
// of 0 bits is absent). glass keeps the storage either way (docs/osmesa.md); what a missing
// buffer changes is what the specification says:
//   - GL_DEPTH_BITS, GL_STENCIL_BITS, GL_ACCUM_*_BITS report 0 (table 6.34);
//   - the depth and stencil tests act as if they pass and write nothing (4.1.5, 4.1.4);
//   - glClear leaves it alone (4.2.3);
//   - glAccum is GL_INVALID_OPERATION (4.2.4), and so are glReadPixels and glCopyPixels of its
//     data (4.3.2, 4.3.3) and glCopyTexImage into a depth texture without a depth buffer
//     (ARB_depth_texture).
//
// Kept with them, though it is no ancillary buffer: whether the colour buffer has alpha
// bitplanes (a GLUT window without GLUT_ALPHA and an OSMesa context of a format without alpha
// have none, as in Mesa). Without them GL_ALPHA_BITS is 0 and the alpha GL reads from the colour
// buffer is 1 (spec 4.1.8, 4.3.2): glass keeps the storage and stores alpha 255 in every pixel it
// writes (storedAlphaWord), so that blending, glReadPixels, glCopyPixels, glAccum and texture
// copies read 1 without a test of their own. Fragment alpha is untouched: the alpha test and
// GL_SRC_ALPHA blending use it as ever.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glass::raster {
class Framebuffer;
}

namespace glass::gl {

struct Context;

struct AncillaryBuffers {
  bool depth = true;
  bool stencil = true;
  bool accumulation = true;
  bool colorAlpha = true;  // the colour buffer's alpha bitplanes
};

// Whether reading pixels of `format` (glReadPixels) or `type` (glCopyPixels: GL_DEPTH,
// GL_STENCIL) finds the buffer they come from; colour always does.
bool hasBufferToRead(const Context& ctx, GLenum formatOrType);

// The depth and stencil tests as they act: enabled and with a buffer to test against.
bool depthTestActive(const Context& ctx);
bool stencilTestActive(const Context& ctx);

// The word every colour pixel written is ORed with (a pixel as packColorBytes lays it out):
// 0 with alpha bitplanes, alpha 255 without them, which the blended or logic-op result's alpha
// then cannot change. One OR per store, so that the draws of a window without alpha keep the
// fast paths that a masked alpha channel would leave.
uint32_t storedAlphaWord(const Context& ctx);

// Sets the alpha of every pixel of the colour buffers (both of a double-buffered framebuffer) to
// 255 (a colour buffer without alpha bitplanes made, resized or given to the context).
void fillColorAlpha(raster::Framebuffer& framebuffer);

// Gives the colour buffer alpha bitplanes or takes them away (glassSetAlphaBitplanes, an OSMesa
// format without alpha), after finishing the drawing queued with the alpha it had.
void setAlphaBitplanes(Context& ctx, bool alpha);

}  // namespace glass::gl
