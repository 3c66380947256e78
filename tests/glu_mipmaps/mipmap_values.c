/* What GLU's mipmap builders hand to GL, and what gluScaleImage writes, printed as one FNV-1a
 * hash per level or image: built once against glass and once against Mesa's libGLU, the two
 * outputs must be the same line for line (compare_outputs.cmake compares them). The program
 * defines glTexImage1D/2D/3D itself (linked with -rdynamic, so GLU calls these), records the
 * elements they are given and passes the call on to the library's own. */
#define _GNU_SOURCE
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int recording;

static int bytesOfType(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    default: return 4;
  }
}

static int componentsOfFormat(GLenum format) {
  switch (format) {
    case GL_RGBA: return 4;
    case GL_RGB: return 3;
    case GL_LUMINANCE_ALPHA: return 2;
    default: return 1;
  }
}

static uint64_t hashBytes(uint64_t hash, const unsigned char* bytes, size_t n) {
  for (size_t k = 0; k < n; ++k) hash = (hash ^ bytes[k]) * 1099511628211ull;
  return hash;
}

/* The elements of a width x height image laid out by the current GL_UNPACK_* state, row by row
 * without the rows' padding. */
static void printLevel(GLint level, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                       const void* data) {
  GLint alignment = 4, rowLength = 0, imageHeight = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
  glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &imageHeight);
  const size_t element = (size_t)bytesOfType(type), group = element * (size_t)componentsOfFormat(format);
  size_t row = group * (size_t)(rowLength > 0 ? rowLength : width);
  if (element < (size_t)alignment) row = (row + (size_t)alignment - 1) / (size_t)alignment * (size_t)alignment;
  const size_t image = row * (size_t)(imageHeight > 0 ? imageHeight : height);
  uint64_t hash = 14695981039346656037ull;
  for (GLsizei k = 0; k < depth; ++k)
    for (GLsizei j = 0; j < height; ++j)
      hash = hashBytes(hash, (const unsigned char*)data + (size_t)k * image + (size_t)j * row, group * (size_t)width);
  printf("  level %d %dx%dx%d type 0x%x hash %016llx\n", level, width, height, depth, type, (unsigned long long)hash);
}

typedef void (*TexImage1DCall)(GLenum, GLint, GLint, GLsizei, GLint, GLenum, GLenum, const void*);
typedef void (*TexImage2DCall)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*);
typedef void (*TexImage3DCall)(GLenum, GLint, GLint, GLsizei, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*);

void glTexImage1D(GLenum target, GLint level, GLint internalFormat, GLsizei width, GLint border, GLenum format,
                  GLenum type, const void* data) {
  static TexImage1DCall library;
  if (!library) library = (TexImage1DCall)dlsym(RTLD_NEXT, "glTexImage1D");
  if (recording && target == GL_TEXTURE_1D && data) printLevel(level, width, 1, 1, format, type, data);
  library(target, level, internalFormat, width, border, format, type, data);
}

void glTexImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height, GLint border,
                  GLenum format, GLenum type, const void* data) {
  static TexImage2DCall library;
  if (!library) library = (TexImage2DCall)dlsym(RTLD_NEXT, "glTexImage2D");
  if (recording && target == GL_TEXTURE_2D && data) printLevel(level, width, height, 1, format, type, data);
  library(target, level, internalFormat, width, height, border, format, type, data);
}

void glTexImage3D(GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height, GLsizei depth,
                  GLint border, GLenum format, GLenum type, const void* data) {
  static TexImage3DCall library;
  if (!library) library = (TexImage3DCall)dlsym(RTLD_NEXT, "glTexImage3D");
  if (recording && target == GL_TEXTURE_3D && data) printLevel(level, width, height, depth, format, type, data);
  library(target, level, internalFormat, width, height, depth, border, format, type, data);
}

static uint32_t randomState = 12345u;
static uint32_t nextRandom(void) {
  randomState = randomState * 1664525u + 1013904223u;
  return randomState >> 8;
}

/* n random elements of `type`; ints are kept non-negative (libGLU halves a one-texel-wide GL_INT
 * image as unsigned values, which glass does not copy: docs/texturing.md). Floats lie in
 * [-0.1, 1.1] for colours and are whole numbers for indices. The image is followed by zeros. */
static void* randomImage(size_t n, GLenum type, GLenum format, int forMipmaps) {
  /* libGLU's box filter may read the row (or texel) after the image, with weight 0: zeros there
   * keep its result from depending on what the heap holds (glass reads the last one instead). */
  unsigned char* data = calloc(n * 4 + 65536, 1);
  for (size_t k = 0; k < n; ++k) {
    const uint32_t r = nextRandom();
    switch (type) {
      case GL_UNSIGNED_BYTE: case GL_BYTE: data[k] = (unsigned char)r; break;
      case GL_UNSIGNED_SHORT: case GL_SHORT: { const uint16_t v = (uint16_t)r; memcpy(data + 2 * k, &v, 2); break; }
      case GL_UNSIGNED_INT: { const uint32_t v = r * 977u; memcpy(data + 4 * k, &v, 4); break; }
      case GL_INT: {
        const int32_t v = forMipmaps ? (int32_t)((r * 977u) >> 1) : (int32_t)(r * 977u);
        memcpy(data + 4 * k, &v, 4);
        break;
      }
      default: {
        const float v = format == GL_COLOR_INDEX ? (float)(r % 300) : (float)(r % 120000) / 99999.0f - 0.1f;
        memcpy(data + 4 * k, &v, 4);
        break;
      }
    }
  }
  return data;
}

static const GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
enum { kTypeCount = sizeof kTypes / sizeof kTypes[0] };

int main(void) {
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  static unsigned char framebuffer[16 * 16 * 4];
  if (!context || !OSMesaMakeCurrent(context, framebuffer, GL_UNSIGNED_BYTE, 16, 16)) {
    fprintf(stderr, "no OSMesa context\n");
    return 1;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);

  /* gluBuild2DMipmaps and gluBuild1DMipmaps: sizes that enlarge, reduce, both, or stay. */
  static const int sizes[][2] = {{48, 48}, {100, 30}, {80, 80}, {5, 7}, {33, 65}, {250, 3}, {1, 100}, {17, 200}, {16, 8}};
  static const GLenum mipmapFormats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE};
  recording = 1;
  for (int dimensions = 1; dimensions <= 2; ++dimensions)
    for (int t = 0; t < kTypeCount; ++t)
      for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
        for (size_t f = 0; f < sizeof mipmapFormats / sizeof mipmapFormats[0]; ++f) {
          const int width = sizes[s][0], height = dimensions == 2 ? sizes[s][1] : 1;
          void* data = randomImage((size_t)width * (size_t)height * (size_t)componentsOfFormat(mipmapFormats[f]),
                                   kTypes[t], mipmapFormats[f], 1);
          printf("gluBuild%dDMipmaps %dx%d format 0x%x type 0x%x\n", dimensions, width, height, mipmapFormats[f], kTypes[t]);
          const GLint result =
              dimensions == 1
                  ? gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGBA, width, mipmapFormats[f], kTypes[t], data)
                  : gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, width, height, mipmapFormats[f], kTypes[t], data);
          printf("  result %d\n", result);
          free(data);
        }

  /* gluBuild3DMipmaps: sizes that libGLU builds right (it reads past a level whose height is 1
   * before its width is, as for 2 x 1 x 5, and crashes on 1 x 9 x 2: docs/texturing.md). */
  static const int volumes[][3] = {{6, 5, 3}, {8, 8, 8}, {12, 3, 5}, {7, 7, 7}, {16, 4, 2}, {3, 3, 3}, {10, 12, 6}, {5, 1, 1}};
  for (int t = 0; t < kTypeCount; ++t)
    for (size_t v = 0; v < sizeof volumes / sizeof volumes[0]; ++v)
      for (size_t f = 0; f < sizeof mipmapFormats / sizeof mipmapFormats[0]; ++f) {
        const int width = volumes[v][0], height = volumes[v][1], depth = volumes[v][2];
        void* data = randomImage((size_t)width * (size_t)height * (size_t)depth *
                                     (size_t)componentsOfFormat(mipmapFormats[f]),
                                 kTypes[t], mipmapFormats[f], 1);
        printf("gluBuild3DMipmaps %dx%dx%d format 0x%x type 0x%x\n", width, height, depth, mipmapFormats[f], kTypes[t]);
        printf("  result %d\n", gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, width, height, depth, mipmapFormats[f],
                                                   kTypes[t], data));
        free(data);
      }
  recording = 0;

  /* gluScaleImage from every type to every type, colours and indices. */
  static const int scales[][4] = {{48, 48, 64, 64}, {100, 30, 37, 51}, {8, 8, 4, 4}, {5, 7, 13, 2}, {33, 65, 32, 64}};
  static const GLenum scaleFormats[] = {GL_RGB, GL_LUMINANCE, GL_COLOR_INDEX};
  for (int in = 0; in < kTypeCount; ++in)
    for (int out = 0; out < kTypeCount; ++out)
      for (size_t s = 0; s < sizeof scales / sizeof scales[0]; ++s)
        for (size_t f = 0; f < sizeof scaleFormats / sizeof scaleFormats[0]; ++f) {
          const int components = componentsOfFormat(scaleFormats[f]);
          const size_t n = (size_t)scales[s][0] * (size_t)scales[s][1] * (size_t)components;
          const size_t m = (size_t)scales[s][2] * (size_t)scales[s][3] * (size_t)components;
          void* data = randomImage(n, kTypes[in], scaleFormats[f], 0);
          unsigned char* result = calloc(m, 4);
          const GLint status = gluScaleImage(scaleFormats[f], scales[s][0], scales[s][1], kTypes[in], data,
                                             scales[s][2], scales[s][3], kTypes[out], result);
          printf("gluScaleImage %dx%d 0x%x -> %dx%d 0x%x format 0x%x: result %d hash %016llx\n", scales[s][0],
                 scales[s][1], kTypes[in], scales[s][2], scales[s][3], kTypes[out], scaleFormats[f], status,
                 (unsigned long long)hashBytes(14695981039346656037ull, result, m * (size_t)bytesOfType(kTypes[out])));
          free(data);
          free(result);
        }
  OSMesaDestroyContext(context);
  return 0;
}
