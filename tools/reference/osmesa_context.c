/* glass/context.h implemented on Mesa's off-screen renderer, OSMesa.
 *
 * A GL test program calls only GL, GLU and the four glass context functions. Linked with this
 * file, libOSMesa and libGLU instead of libglass, the same source renders with Mesa, and that
 * picture is the reference glass is compared against. The context matches what glass promises:
 * RGBA8 colour, 24-bit depth, 8-bit stencil, a 16-bit-per-channel accumulation buffer.
 */
#include <glass/context.h>

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

/* Mesa's gallium frontends cap textures and render buffers at 16384 pixels a side. */
enum { MAX_SIZE = 16384 };

struct GlassContext {
  OSMesaContext osmesa;
  int width;
  int height;
  unsigned char *pixels; /* the colour buffer OSMesa renders into, bottom row first */
};

GlassContext *glassCreateContext(int width, int height) {
  GlassContext *ctx;
  if (width <= 0 || height <= 0 || width > MAX_SIZE || height > MAX_SIZE) return NULL;

  ctx = calloc(1, sizeof *ctx);
  if (!ctx) return NULL;
  ctx->width = width;
  ctx->height = height;
  ctx->pixels = malloc((size_t)width * (size_t)height * 4);
  ctx->osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
  if (!ctx->pixels || !ctx->osmesa) {
    glassDestroyContext(ctx);
    return NULL;
  }
  return ctx;
}

/* The GlassContext whose OSMesa context is current on this thread. */
static _Thread_local GlassContext *current_context;

int glassMakeCurrent(GlassContext *ctx) {
  GLboolean made;
  if (!ctx)
    made = OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  else
    made = OSMesaMakeCurrent(ctx->osmesa, ctx->pixels, GL_UNSIGNED_BYTE, ctx->width, ctx->height);
  if (made == GL_TRUE) current_context = ctx;
  return made == GL_TRUE;
}

GlassContext *glassGetCurrentContext(void) { return current_context; }

int glassGetWidth(const GlassContext *ctx) { return ctx ? ctx->width : 0; }

int glassGetHeight(const GlassContext *ctx) { return ctx ? ctx->height : 0; }

/* A new OSMesa context, in GL's initial state, sharing the old one's display lists and texture
 * objects and rendering into the same colour buffer. Its depth, stencil and accumulation
 * buffers are new: glass keeps theirs, but the frames this serves clear them first. */
int glassResetContext(GlassContext *ctx) {
  OSMesaContext fresh;
  if (!ctx) return 0;
  if (ctx == current_context) glFinish();
  fresh = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, ctx->osmesa);
  if (!fresh) return 0;
  if (ctx == current_context &&
      OSMesaMakeCurrent(fresh, ctx->pixels, GL_UNSIGNED_BYTE, ctx->width, ctx->height) != GL_TRUE) {
    OSMesaDestroyContext(fresh);
    return 0;
  }
  OSMesaDestroyContext(ctx->osmesa);
  ctx->osmesa = fresh;
  return 1;
}

/* OSMesa renders into ctx->pixels, RGBA bottom row first, complete once drawing is finished. */
const unsigned char *glassGetColorBuffer(const GlassContext *ctx) {
  if (!ctx) return NULL;
  if (ctx == current_context) glFinish();
  return ctx->pixels;
}

void glassDestroyContext(GlassContext *ctx) {
  if (!ctx) return;
  if (ctx == current_context) glassMakeCurrent(NULL);
  if (ctx->osmesa) OSMesaDestroyContext(ctx->osmesa);
  free(ctx->pixels);
  free(ctx);
}

/* A short write sets the stream's error flag, which glassWritePNG checks before the rename. */
static void write_to_file(void *file, void *data, int size) {
  fwrite(data, 1, (size_t)size, (FILE *)file);
}

/* Writes the colour buffer as an RGB PNG, top row first. The file appears whole or not at all:
 * the PNG goes to a temporary file next to the target, which is renamed over it when complete. */
int glassWritePNG(GlassContext *ctx, const char *path) {
  const size_t row_bytes = ctx ? (size_t)ctx->width * 3 : 0;
  unsigned char *rgb;
  char *temp_path;
  FILE *file;
  int ok;
  if (!ctx || !path) return 0;

  /* GL's rows run bottom to top (OSMESA_Y_UP is 1); PNG rows run top to bottom. */
  const unsigned char *pixels = glassGetColorBuffer(ctx);
  rgb = malloc(row_bytes * (size_t)ctx->height);
  if (!rgb) return 0;
  for (int y = 0; y < ctx->height; ++y) {
    const unsigned char *src = pixels + (size_t)(ctx->height - 1 - y) * ctx->width * 4;
    unsigned char *dst = rgb + (size_t)y * row_bytes;
    for (int x = 0; x < ctx->width; ++x) memcpy(dst + 3 * x, src + 4 * x, 3);
  }

  temp_path = malloc(strlen(path) + 32);
  if (!temp_path) {
    free(rgb);
    return 0;
  }
  sprintf(temp_path, "%s.tmp%ld", path, (long)getpid());
  file = fopen(temp_path, "wb");
  ok = file != NULL;
  if (ok) {
    ok = stbi_write_png_to_func(write_to_file, file, ctx->width, ctx->height, 3, rgb,
                                (int)row_bytes) != 0;
    ok = !ferror(file) && ok;
    ok = fclose(file) == 0 && ok;
    ok = ok && rename(temp_path, path) == 0;
    if (!ok) remove(temp_path);
  }
  free(temp_path);
  free(rgb);
  return ok;
}
