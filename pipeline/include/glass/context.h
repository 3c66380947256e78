/* glass: an offscreen OpenGL 1.x context that renders into memory.
 *
 * A context owns a framebuffer of RGBA8 colour, a 24-bit depth buffer, an 8-bit stencil
 * buffer and an accumulation buffer of 16 bits per channel (allocated when first used). GL calls
 * act on the context that is current on the calling thread; with no current context they do
 * nothing.
 *
 *   GlassContext *ctx = glassCreateContext(640, 480);
 *   glassMakeCurrent(ctx);
 *   ... GL calls ...
 *   glassWritePNG(ctx, "picture.png");
 *   glassDestroyContext(ctx);
 */
#ifndef GLASS_CONTEXT_H
#define GLASS_CONTEXT_H

#if defined(__GNUC__)
#  define GLASS_API extern __attribute__((visibility("default")))
#else
#  define GLASS_API extern
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef struct GlassContext GlassContext;

/* RGBA8 colour, depth >= 24 bits, 8-bit stencil, 16-bit accumulation; NULL on a bad size or no
 * memory.
 * Sizes from 1 to 16384 pixels a side are accepted. */
GLASS_API GlassContext *glassCreateContext(int width, int height);

/* Makes ctx current on the calling thread; 1 on success. NULL releases the current context. */
GLASS_API int glassMakeCurrent(GlassContext *ctx);

/* Frees the context; if it is current on the calling thread, no context is current after. */
GLASS_API void glassDestroyContext(GlassContext *ctx);

/* Writes the colour buffer as an RGB PNG (top row first, alpha left out); 1 on success. The file
 * is written whole or not at all: the PNG goes to a temporary file in the same directory, which
 * is renamed over path when complete. */
GLASS_API int glassWritePNG(GlassContext *ctx, const char *path);

/* The context current on the calling thread, or NULL. */
GLASS_API GlassContext *glassGetCurrentContext(void);

/* The framebuffer size; 0 for a NULL context. */
GLASS_API int glassGetWidth(const GlassContext *ctx);
GLASS_API int glassGetHeight(const GlassContext *ctx);

/* The colour buffer: width * height pixels of 4 bytes (R, G, B, A), bottom row first as in GL,
 * rows packed without padding; the back buffer of a double-buffered context
 * (glassSetDoubleBuffered). Valid until the context is destroyed or resized. NULL for a NULL
 * context. glassWritePNG writes the same buffer. */
GLASS_API const unsigned char *glassGetColorBuffer(const GlassContext *ctx);

/* Puts ctx back in GL's initial state, every value as a new context of its size has it, and
 * keeps what a program draws frame after frame with: its display lists and named texture
 * objects, the contents of its buffers, its flush callback and its teaching view. For drawing
 * independent frames in one context without making a new one each time (glass view does), so
 * that each frame starts as it would in a new context. If ctx is current on the calling thread it
 * stays current; it must not be current on another thread. 1 on success; 0 on a NULL context or
 * no memory, and then nothing changed. */
GLASS_API int glassResetContext(GlassContext *ctx);

/* Which ancillary buffers the framebuffer has; a new context has all three. Nonzero asks for the
 * buffer, 0 leaves it out, and then GL acts as OpenGL 1.x says of a framebuffer without it: its
 * bits read 0 (GL_DEPTH_BITS, ...), the depth or stencil test passes and writes nothing, glClear
 * leaves it alone, and glAccum and reading its pixels are GL_INVALID_OPERATION. glass's GLUT
 * takes them from the display mode (GLUT_DEPTH, GLUT_STENCIL, GLUT_ACCUM). Kept by
 * glassResetContext and glassResizeContext. 1 on success; 0 on a NULL context. */
GLASS_API int glassSetAncillaryBuffers(GlassContext *ctx, int depth, int stencil, int accumulation);

/* Whether the colour buffer has alpha bitplanes; a new context has them. 0 leaves them out, as
 * Mesa does for a GLUT window without GLUT_ALPHA and an OSMesa context of a format without
 * alpha, and then GL acts as OpenGL 1.x says of such a colour buffer: GL_ALPHA_BITS reads 0, and
 * the destination alpha of blending and the alpha glReadPixels, glCopyPixels and glAccum read
 * are 1. glass keeps 4 bytes a pixel and stores alpha 255 in every pixel: the buffer's alpha
 * becomes 255 at once, and glClear, drawing, glDrawPixels, glCopyPixels, glBitmap and
 * glAccum(GL_RETURN) write 255 whatever the colour's alpha, which the alpha test and GL_SRC_ALPHA
 * blending still use; glColorMask's alpha is kept and queried as set. Nonzero gives the
 * bitplanes back (the stored alphas stay 255 until drawn over). glass's GLUT takes it from the
 * display mode (GLUT_ALPHA). Kept by glassResetContext and glassResizeContext. 1 on success; 0
 * on a NULL context. */
GLASS_API int glassSetAlphaBitplanes(GlassContext *ctx, int alpha);

/* For window systems (glass's GLUT): the hooks a window needs to show a context's picture. */

/* Gives the framebuffer a new size, as a window's resize does; GL state (matrices, viewport,
 * lights, textures, lists) is kept, the viewport included (a GLUT reshape sets it), and the
 * colour, depth, stencil and accumulation buffers start again cleared to zero (alpha 255 without
 * alpha bitplanes). 1 on success; 0 on a NULL context, a size outside 1 to 16384 or no memory,
 * and then nothing changed. */
GLASS_API int glassResizeContext(GlassContext *ctx, int width, int height);

/* Called on the calling thread after glFlush or glFinish has put every queued draw of ctx into
 * its colour buffer (not after a call refused between glBegin and glEnd), with ctx current:
 * a single-buffered window shows its picture there. NULL removes it. One callback per context. */
typedef void (*GlassFlushCallback)(GlassContext *ctx, void *userData);
GLASS_API void glassSetFlushCallback(GlassContext *ctx, GlassFlushCallback callback, void *userData);

/* Gives ctx a front and a back colour buffer (nonzero) or one (0), as a window of a
 * double-buffered or single-buffered visual has; a new context has one. With two, GL acts as
 * OpenGL 1.x says of a double-buffered framebuffer: GL_DOUBLEBUFFER is true, the draw and read
 * buffers start as GL_BACK (GL_FRONT with one), glDrawBuffer and glReadBuffer choose GL_FRONT,
 * GL_BACK or, for drawing, GL_FRONT_AND_BACK (each buffer blended with its own pixels), and
 * glClear and glAccum(GL_RETURN) write the draw buffers. The new front buffer is a copy of the
 * colour buffer; setting the draw and read buffers to their initial values finishes the call.
 * glass's GLUT takes it from the display mode (GLUT_DOUBLE). Kept by glassResetContext and
 * glassResizeContext. 1 on success; 0 on a NULL context, a call between glBegin and glEnd or no
 * memory, and then nothing changed. */
GLASS_API int glassSetDoubleBuffered(GlassContext *ctx, int doubleBuffered);

/* Copies the back buffer of a double-buffered context into its front buffer, after finishing
 * every queued draw (the back buffer keeps its pixels, as Mesa's swap leaves them): what a
 * window's swap does before it shows the front buffer. Does nothing to a single-buffered
 * context. 1 on success; 0 on a NULL context. */
GLASS_API int glassSwapBuffers(GlassContext *ctx);

/* The front buffer of a double-buffered context, the picture a window shows, as
 * glassGetColorBuffer gives the back one; the colour buffer of a single-buffered context. */
GLASS_API const unsigned char *glassGetFrontBuffer(const GlassContext *ctx);

/* Writes width * height RGBA8 pixels (bottom row first, rows packed, as glassGetColorBuffer gives
 * them) as an RGB PNG, whole or not at all, as glassWritePNG does; 1 on success. For a copy of a
 * picture kept after the context drew on. */
GLASS_API int glassWritePixelsPNG(const char *path, int width, int height,
                                  const unsigned char *rgba);

/* The teaching view ctx's pictures show (docs/teaching.md): "depth", "overdraw", "wireframe",
 * "normals" or "mipmap", or NULL for the program's own colours; GLASS_VIEW sets it when a context
 * is created, glass's GLUT switches it on Ctrl+Alt+V. The view gathers from the next draw on.
 * 1 on success; 0 for a NULL context, an unknown name or a call between glBegin and glEnd, and
 * then nothing changed. */
GLASS_API int glassSetView(GlassContext *ctx, const char *name);
/* The name of ctx's view, or NULL when it shows the program's colours (or ctx is NULL). */
GLASS_API const char *glassGetView(const GlassContext *ctx);

#ifdef __cplusplus
}
#endif

#endif /* GLASS_CONTEXT_H */
