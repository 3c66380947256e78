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

/* The elements of a width x height image laid out by the current GL_UNPACK_* state (rows and
 * texels skipped, rows padded), row by row without the rows' padding. */
static void printLevel(GLint level, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                       const void* data) {
  GLint alignment = 4, rowLength = 0, imageHeight = 0, skipRows = 0, skipPixels = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
  glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &imageHeight);
  glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
  const size_t element = (size_t)bytesOfType(type), group = element * (size_t)componentsOfFormat(format);
  size_t row = group * (size_t)(rowLength > 0 ? rowLength : width);
  if (element < (size_t)alignment) row = (row + (size_t)alignment - 1) / (size_t)alignment * (size_t)alignment;
  const size_t image = row * (size_t)(imageHeight > 0 ? imageHeight : height);
  uint64_t hash = 14695981039346656037ull;
  data = (const unsigned char*)data + (size_t)skipRows * row + (size_t)skipPixels * group;
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

/* The levels of the bound 2D texture from 0 on, as glGetTexImage reads them in RGBA bytes (a level
 * of width 0 ends them), one hash each. The texture is then cleared for the next case. */
static void printTextureLevels(void) {
  for (GLint level = 0;; ++level) {
    GLint width = 0, height = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &height);
    if (width == 0 || height == 0) break;
    const size_t n = (size_t)width * (size_t)height * 4;
    unsigned char* texels = calloc(n, 1);
    glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    printf("    texture level %d %dx%d hash %016llx\n", level, width, height,
           (unsigned long long)hashBytes(14695981039346656037ull, texels, n));
    free(texels);
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  }
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

  /* Unsigned bytes as programs hand them over, through the unpack layouts they use: sizes that
   * need no resampling (the bytes halved as they are), every format with one to four components,
   * rows padded and skipped; and gluBuild2DMipmapLevels, also of sides that are not powers of
   * two, from level 0 and from a later level with base and max inside the chain. What is
   * compared is the texture's levels as glGetTexImage reads them (libGLU hands GL_BGRA levels
   * over in another layout than it was given, to the same texels). Two kinds of case are marked
   * "glass only" and left out of the comparison with libGLU, which gets them wrong (the same
   * texels laid out otherwise give it other levels): one texel wide with rows padded or spaced,
   * and resampled along x only, where its last row comes out as zeros. */
  glBindTexture(GL_TEXTURE_2D, 1);  /* a texture of its own, without the levels of the cases above */
  static const int byteSizes[][2] = {{64, 32}, {1, 16}, {8, 1}, {2, 2}, {1, 1}, {128, 4}, {6, 4}, {8, 3}};
  static const GLenum byteFormats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE_ALPHA, GL_LUMINANCE, GL_ALPHA, GL_BGRA};
  static const int layouts[][4] = {{1, 0, 0, 0}, {4, 0, 0, 0}, {8, 3, 2, 1}, {2, 5, 0, 3}};
  for (size_t s = 0; s < sizeof byteSizes / sizeof byteSizes[0]; ++s)
    for (size_t f = 0; f < sizeof byteFormats / sizeof byteFormats[0]; ++f)
      for (size_t u = 0; u < sizeof layouts / sizeof layouts[0]; ++u) {
        const int width = byteSizes[s][0], height = byteSizes[s][1];
        const int alignment = layouts[u][0], rowLength = layouts[u][1] > 0 ? width + layouts[u][1] : 0;
        const int skipRows = layouts[u][2], skipPixels = layouts[u][3];
        const size_t group = (size_t)componentsOfFormat(byteFormats[f]);
        const size_t rowTexels = (size_t)(rowLength > 0 ? rowLength : width);
        const size_t n = (rowTexels * (size_t)(height + skipRows) + (size_t)skipPixels + 8) * group * 2;
        void* data = randomImage(n, GL_UNSIGNED_BYTE, byteFormats[f], 1);
        glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, skipRows);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipPixels);
        const int spaced = rowLength > 0 || (group * (size_t)width) % (size_t)alignment != 0;
        int last = 0;
        while ((width >> last) > 1 || (height >> last) > 1) ++last;
        const int resampledAlongX = (width & (width - 1)) != 0 && (height & (height - 1)) == 0;
        const char* prefix = (width == 1 && spaced) || resampledAlongX ? "glass only: " : "";
        printf("%sbytes %dx%d format 0x%x alignment %d row length %d skip rows %d pixels %d\n", prefix, width,
               height, byteFormats[f], alignment, rowLength, skipRows, skipPixels);
        fflush(stdout);  /* the case is on record if a library fails in it */
        printf("  gluBuild2DMipmaps result %d\n",
               gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, width, height, byteFormats[f], GL_UNSIGNED_BYTE, data));
        printTextureLevels();
        printf("  gluBuild2DMipmapLevels 0 0 %d result %d\n", last,
               gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, width, height, byteFormats[f], GL_UNSIGNED_BYTE, 0, 0,
                                      last, data));
        printTextureLevels();
        printf("  gluBuild2DMipmapLevels 2 3 %d result %d\n", last + 1,
               gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, width, height, byteFormats[f], GL_UNSIGNED_BYTE, 2, 3,
                                      last + 1, data));
        printTextureLevels();
        free(data);
      }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);

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
