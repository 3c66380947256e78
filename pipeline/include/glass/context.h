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
 * rows packed without padding. Valid until the context is destroyed. NULL for a NULL context. */
GLASS_API const unsigned char *glassGetColorBuffer(const GlassContext *ctx);

#ifdef __cplusplus
}
#endif

#endif /* GLASS_CONTEXT_H */
