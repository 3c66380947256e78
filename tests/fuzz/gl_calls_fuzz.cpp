// Fuzz target for the GL API: the input bytes are a program, a sequence of GL, GLU and GLUT calls
// with arguments taken from the bytes, drawn into a fresh 48 x 40 context. GL calls with bad
// enums, sizes, orders or values must set GL errors (or be ignored as the specification says),
// never crash, hang, leak or read out of bounds.
//
// Arguments mix valid and invalid values: enums come from a pool of real names plus numbers no
// enum has, sizes include 0, negative and huge ones, floats include NaN, infinities and 1e30.
// Only where GL reads or writes client memory are the arguments held to what the buffers here can
// hold (a program that lies about its own arrays has undefined behaviour in GL too): image sizes
// with client pixels stay within the pixel buffers, array indices within the arrays.
//
// Built with libFuzzer when GLASS_FUZZ is on (clang), and always as a replay program that runs the
// stored corpus (tests/fuzz/CMakeLists.txt).
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>
#include <glass/context.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <tuple>
#include <vector>

namespace {

// Reads the input bytes as arguments; past the end every read gives zero.
class ByteReader {
public:
  ByteReader(const std::uint8_t *data, std::size_t size) : data_(data), size_(size) {}

  bool done() const { return at_ >= size_; }
  std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  std::uint16_t u16() {
    const std::uint16_t low = byte();
    return static_cast<std::uint16_t>(low | (byte() << 8));
  }
  std::uint32_t u32() {
    const std::uint32_t low = u16();
    return low | (static_cast<std::uint32_t>(u16()) << 16);
  }

  // A small integer in [0, n).
  int below(int n) { return n <= 0 ? 0 : byte() % n; }

  // A size or count: mostly small, sometimes 0, negative or huge.
  int size() {
    switch (byte() % 16) {
    case 0: return 0;
    case 1: return -1;
    case 2: return -byte();
    case 3: return std::numeric_limits<int>::max();
    case 4: return 1 << (byte() % 31);
    default: return byte() % 20;
    }
  }

  // A float: mostly ordinary values, sometimes special ones.
  float real() {
    switch (byte() % 24) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    case 2: return -std::numeric_limits<float>::infinity();
    case 3: return 1e30f;
    case 4: return -1e30f;
    case 5: return 0.0f;
    case 6: return -0.0f;
    case 7: return std::numeric_limits<float>::denorm_min();
    case 8: {
      float f;
      const std::uint32_t bits = u32();
      std::memcpy(&f, &bits, sizeof f);
      return f;
    }
    default: return (static_cast<int>(u16()) - 32768) / 4096.0f;
    }
  }

  GLenum enumFrom(const GLenum *pool, std::size_t count) {
    const std::uint8_t pick = byte();
    if (pick >= 250) return 0x1234 + pick; // no GL enum has these values
    return pool[pick % count];
  }

private:
  const std::uint8_t *data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

// Every enum the calls below take, valid for some call or other: each call picks from all of
// them, so most picks are wrong for the call and must be refused with GL_INVALID_ENUM.
constexpr GLenum kEnums[] = {
    GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP, GL_TRIANGLES, GL_TRIANGLE_STRIP,
    GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON, GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE,
    GL_LIGHTING, GL_LIGHT0, GL_LIGHT7, GL_TEXTURE_1D, GL_TEXTURE_2D, GL_FOG, GL_ALPHA_TEST,
    GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_COLOR_MATERIAL, GL_NORMALIZE, GL_RESCALE_NORMAL,
    GL_CLIP_PLANE0, GL_CLIP_PLANE5, GL_POLYGON_STIPPLE, GL_LINE_STIPPLE, GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_COLOR_LOGIC_OP, GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q, GL_AUTO_NORMAL, GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4, GL_MAP1_COLOR_4, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_2, GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_2, GL_POINT_SMOOTH,
    GL_LINE_SMOOTH, GL_POLYGON_SMOOTH, GL_DITHER, GL_COLOR_SUM, GL_MODELVIEW, GL_PROJECTION,
    GL_TEXTURE, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_CW, GL_CCW, GL_POINT, GL_LINE, GL_FILL,
    GL_FLAT, GL_SMOOTH, GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL,
    GL_ALWAYS, GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_DST_COLOR, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR,
    GL_KEEP, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP, GL_CLEAR,
    GL_AND, GL_XOR, GL_COPY, GL_SET, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION,
    GL_SPOT_DIRECTION, GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
    GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION, GL_EMISSION, GL_SHININESS,
    GL_AMBIENT_AND_DIFFUSE, GL_COLOR_INDEXES, GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER,
    GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR,
    GL_FOG_MODE, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_COLOR, GL_LINEAR, GL_EXP,
    GL_EXP2, GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE, GL_FRAGMENT_DEPTH,
    GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T,
    GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD, GL_TEXTURE_BASE_LEVEL,
    GL_TEXTURE_MAX_LEVEL, GL_GENERATE_MIPMAP, GL_TEXTURE_PRIORITY, GL_NEAREST,
    GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_LINEAR,
    GL_LINEAR_MIPMAP_NEAREST, GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_TEXTURE_ENV,
    GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_MODULATE, GL_DECAL, GL_ADD, GL_S, GL_T, GL_R,
    GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE, GL_OBJECT_LINEAR, GL_EYE_LINEAR,
    GL_SPHERE_MAP, GL_RGB, GL_RGBA, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY,
    GL_RED, GL_GREEN, GL_BLUE, GL_BGR, GL_BGRA, GL_COLOR_INDEX, GL_STENCIL_INDEX,
    GL_DEPTH_COMPONENT, GL_BITMAP, GL_RGB8, GL_RGBA8, GL_RGB5_A1, GL_ALPHA8, GL_LUMINANCE8,
    GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT,
    GL_DOUBLE, GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_SHORT_4_4_4_4_REV,
    GL_UNSIGNED_INT_8_8_8_8, GL_UNSIGNED_INT_2_10_10_10_REV, GL_2_BYTES, GL_3_BYTES, GL_4_BYTES,
    GL_COLOR, GL_DEPTH, GL_STENCIL, GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_RENDER, GL_SELECT,
    GL_FEEDBACK, GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE,
    GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY,
    GL_INDEX_ARRAY, GL_FOG_COORDINATE_ARRAY, GL_SECONDARY_COLOR_ARRAY, GL_V2F, GL_V3F, GL_C4UB_V2F,
    GL_C3F_V3F, GL_N3F_V3F, GL_T2F_V3F, GL_T2F_C4UB_V3F, GL_T4F_C4F_N3F_V4F, GL_COMPILE,
    GL_COMPILE_AND_EXECUTE, GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
    GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_PACK_ALIGNMENT,
    GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_MAP_COLOR, GL_MAP_STENCIL,
    GL_RED_SCALE, GL_RED_BIAS, GL_DEPTH_SCALE, GL_INDEX_SHIFT, GL_PIXEL_MAP_I_TO_R,
    GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_I, GL_FASTEST, GL_NICEST,
    GL_DONT_CARE, GL_PERSPECTIVE_CORRECTION_HINT, GL_VENDOR, GL_RENDERER, GL_VERSION,
    GL_EXTENSIONS, GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX, GL_TEXTURE_MATRIX, GL_VIEWPORT,
    GL_CURRENT_COLOR, GL_CURRENT_RASTER_POSITION, GL_MAX_TEXTURE_SIZE, GL_DEPTH_RANGE,
    GL_POLYGON_MODE, GL_COLOR_WRITEMASK, GL_SCISSOR_BOX, GL_LIST_INDEX, GL_ATTRIB_STACK_DEPTH,
    GL_FRONT_LEFT, GL_BACK_RIGHT, GL_AUX0, GL_NONE, GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_MIN, GL_MAX,
    GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE7, GL_COMBINE, GL_COMBINE_RGB, GL_DOT3_RGB,
    GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE,
    GL_POINT_DISTANCE_ATTENUATION, GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH, GLU_FILL, GLU_LINE,
    GLU_SILHOUETTE, GLU_POINT, GLU_SMOOTH, GLU_FLAT, GLU_NONE, GLU_INSIDE, GLU_OUTSIDE,
    GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO,
    GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO,
    GLU_TESS_BOUNDARY_ONLY, GLU_TESS_TOLERANCE, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, GL_PROXY_TEXTURE_CUBE_MAP,
    GL_REFLECTION_MAP, GL_NORMAL_MAP, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT, GL_TEXTURE_WRAP_R,
    GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL, GL_COMBINE_ALPHA, GL_SOURCE0_RGB,
    GL_SOURCE2_ALPHA, GL_OPERAND0_RGB, GL_OPERAND1_ALPHA, GL_RGB_SCALE, GL_ALPHA_SCALE,
    GL_SUBTRACT, GL_INTERPOLATE, GL_ADD_SIGNED, GL_DOT3_RGBA, GL_PREVIOUS, GL_PRIMARY_COLOR,
    GL_CONSTANT, GL_TEXTURE3, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_POINT_SIZE_MIN,
    GL_CURRENT_SECONDARY_COLOR, GL_CURRENT_FOG_COORDINATE, GL_DRAW_BUFFER, GL_READ_BUFFER,
    GL_FRONT_RIGHT, GL_LEFT,
};
constexpr std::size_t kEnumCount = sizeof kEnums / sizeof kEnums[0];

constexpr GLbitfield kClearMasks[] = {
    GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_STENCIL_BUFFER_BIT, GL_ACCUM_BUFFER_BIT,
    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, 0x80000000u, 0};
constexpr GLbitfield kAttribMasks[] = {GL_ALL_ATTRIB_BITS, GL_CURRENT_BIT, GL_ENABLE_BIT,
                                       GL_TEXTURE_BIT, GL_LIGHTING_BIT, GL_COLOR_BUFFER_BIT,
                                       GL_TRANSFORM_BIT, GL_VIEWPORT_BIT, GL_PIXEL_MODE_BIT,
                                       GL_POLYGON_STIPPLE_BIT, 0};

// Client memory the calls read from or write into. Image sizes with client data are held to at
// most kMaxImageSide pixels a side, and the pixel-store settings to at most kMaxRowLength and
// kMaxSkip, so that no packing reads past kPixelBytes (8 doubles a pixel at most).
constexpr int kMaxImageSide = 16;
constexpr int kMaxRowLength = 32;
constexpr int kMaxSkip = 4;
// A 3D image adds at most kMaxSkip + 4 slices of kMaxImageSide + kMaxSkip rows each.
constexpr std::size_t kPixelBytes =
    (kMaxSkip + 4) * (kMaxSkip + kMaxImageSide + 1) * (kMaxRowLength + kMaxSkip + 8) * 64;

// Vertex arrays: at most kMaxArrayVertices vertices of at most kMaxArrayStride bytes.
constexpr int kMaxArrayVertices = 40;
constexpr int kMaxArrayStride = 128;

struct Memory {
  std::vector<std::uint8_t> pixels = std::vector<std::uint8_t>(kPixelBytes);
  std::vector<std::uint8_t> readback = std::vector<std::uint8_t>(kPixelBytes);
  std::vector<std::uint8_t> arrays = std::vector<std::uint8_t>(kMaxArrayVertices * kMaxArrayStride + 64);
  std::array<GLuint, 64> indices{};
  std::array<GLuint, 256> select{};
  std::array<GLfloat, 512> feedback{};
  std::array<GLdouble, 256> got{};
  std::array<GLdouble, 3 * 64> tessVertices{};
  std::array<GLdouble, 3 * 256> tessCombined{};
  std::size_t tessCombinedUsed = 0;
  // The texture image glGetTexImage may return: textures with client data are small, but
  // glTexImage with no data and glCopyTexImage make them up to kMaxTextureSideForRead.
  std::vector<std::uint8_t> textureReadback;
};

// glGetTexImage writes the whole level; a texture made with a null pointer may be as large as GL
// allows, so reading back is done only for the levels the fuzzer can prove small enough.
constexpr int kMaxTextureSideForRead = 64;

Memory *memory = nullptr;

// Calls f with arguments read in order. In a call's parentheses C++ leaves the order of the
// arguments' evaluation open (gcc and clang differ), in a braced list it is left to right: so an
// input replays the same GL calls whichever compiler built the program.
#define CALL(f, ...) std::apply(f, std::tuple{__VA_ARGS__})

void GLAPIENTRY tessBegin(GLenum mode) { glBegin(mode); }
void GLAPIENTRY tessVertex(void *data) { glVertex3dv(static_cast<const GLdouble *>(data)); }
void GLAPIENTRY tessEnd() { glEnd(); }
void GLAPIENTRY tessCombine(GLdouble coords[3], void *[4], GLfloat[4], void **out) {
  if (memory->tessCombinedUsed + 3 > memory->tessCombined.size()) memory->tessCombinedUsed = 0;
  GLdouble *slot = &memory->tessCombined[memory->tessCombinedUsed];
  memory->tessCombinedUsed += 3;
  slot[0] = coords[0];
  slot[1] = coords[1];
  slot[2] = coords[2];
  *out = slot;
}

// Clamps the pixel-store state the fuzzer sets so that packing stays inside the buffers.
GLint clampPixelStore(GLenum pname, GLint value) {
  switch (pname) {
  case GL_UNPACK_ROW_LENGTH:
  case GL_PACK_ROW_LENGTH: return value < 0 ? value : value % (kMaxRowLength + 1);
  case GL_UNPACK_SKIP_ROWS:
  case GL_UNPACK_SKIP_PIXELS:
  case GL_PACK_SKIP_ROWS:
  case GL_PACK_SKIP_PIXELS:
  case GL_UNPACK_SKIP_IMAGES: return value < 0 ? value : value % (kMaxSkip + 1);
  case GL_UNPACK_IMAGE_HEIGHT: return value < 0 ? value : value % (kMaxImageSide + 1);
  default: return value;
  }
}

// A side for an image with client pixels: within the buffers, or refused by GL before reading.
int clientImageSide(ByteReader &in) {
  const int side = in.size();
  return side > kMaxImageSide ? kMaxImageSide : side;
}

void fill(ByteReader &in, float *values, int count) {
  for (int i = 0; i < count; ++i) values[i] = in.real();
}

void drawImmediate(ByteReader &in) {
  glBegin(in.enumFrom(kEnums, kEnumCount));
  const int vertices = in.below(12);
  for (int i = 0; i < vertices; ++i) {
    switch (in.below(7)) {
    case 0: CALL(glColor4f, in.real(), in.real(), in.real(), in.real()); break;
    case 1: CALL(glNormal3f, in.real(), in.real(), in.real()); break;
    case 2: CALL(glTexCoord4f, in.real(), in.real(), in.real(), in.real()); break;
    case 3: glEdgeFlag(in.byte() & 1); break;
    case 4: CALL(glMaterialf, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount), in.real()); break;
    case 5:
      switch (in.below(3)) {
      case 0: CALL(glMultiTexCoord4f, in.enumFrom(kEnums, kEnumCount), in.real(), in.real(), in.real(), in.real()); break;
      case 1: CALL(glSecondaryColor3f, in.real(), in.real(), in.real()); break;
      default: glFogCoordf(in.real()); break;
      }
      break;
    default: break;
    }
    CALL(glVertex4f, in.real(), in.real(), in.real(), in.byte() < 200 ? 1.0f : in.real());
  }
  if (in.byte() < 240) glEnd();
}

void setArrays(ByteReader &in) {
  for (std::size_t i = 0; i < memory->arrays.size(); ++i) memory->arrays[i] = in.byte();
  const GLsizei stride = in.below(kMaxArrayStride / 8 + 1) * 8;
  const GLenum type = in.enumFrom(kEnums, kEnumCount);
  void *base = memory->arrays.data();
  switch (in.below(6)) {
  case 0: glVertexPointer(in.below(6), type, stride, base); break;
  case 1: glColorPointer(in.below(6), type, stride, base); break;
  case 2: glNormalPointer(type, stride, base); break;
  case 3: glTexCoordPointer(in.below(6), type, stride, base); break;
  case 4: glEdgeFlagPointer(stride, base); break;
  default: glInterleavedArrays(in.enumFrom(kEnums, kEnumCount), stride, base); break;
  }
  if (in.byte() & 1)
    glEnableClientState(in.enumFrom(kEnums, kEnumCount));
  else
    glDisableClientState(in.enumFrom(kEnums, kEnumCount));
}

void drawArrays(ByteReader &in) {
  // Arrays hold kMaxArrayVertices vertices: first + count and every index stay below that.
  const GLenum mode = in.enumFrom(kEnums, kEnumCount);
  switch (in.below(4)) {
  case 0: {
    const GLint first = in.below(8);
    const int count = in.size();
    glDrawArrays(mode, first, count > kMaxArrayVertices - 8 ? kMaxArrayVertices - 8 : count);
    break;
  }
  case 1:
  case 2: {
    for (auto &index : memory->indices) index = in.below(kMaxArrayVertices);
    std::array<GLubyte, 64> bytes{};
    std::array<GLushort, 64> shorts{};
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      bytes[i] = static_cast<GLubyte>(memory->indices[i]);
      shorts[i] = static_cast<GLushort>(memory->indices[i]);
    }
    const GLenum type = in.enumFrom(kEnums, kEnumCount);
    const void *indices = type == GL_UNSIGNED_BYTE    ? static_cast<const void *>(bytes.data())
                          : type == GL_UNSIGNED_SHORT ? static_cast<const void *>(shorts.data())
                                                      : static_cast<const void *>(memory->indices.data());
    const int count = in.size();
    const GLsizei n = count > 64 ? 64 : count;
    if (in.byte() & 1)
      glDrawElements(mode, n, type, indices);
    else
      CALL(glDrawRangeElements, mode, in.below(kMaxArrayVertices), in.below(kMaxArrayVertices), n, type, indices);
    break;
  }
  default: glArrayElement(in.below(kMaxArrayVertices)); break;
  }
}

void textureCall(ByteReader &in) {
  const GLenum target = in.enumFrom(kEnums, kEnumCount);
  const GLenum format = in.enumFrom(kEnums, kEnumCount);
  const GLenum type = in.enumFrom(kEnums, kEnumCount);
  const GLint level = in.byte() < 200 ? in.below(5) : in.size();
  switch (in.below(11)) {
  case 9: {
    // A 3D image with client pixels: at most 16 x 16 x 4 (the image skips and heights the
    // fuzzer sets stay small too).
    const GLsizei w = clientImageSide(in);
    const GLsizei h = clientImageSide(in);
    const int depth = in.size();
    const GLsizei d = depth > 4 ? 4 : depth;
    CALL(glTexImage3D, target, level, static_cast<GLint>(in.enumFrom(kEnums, kEnumCount)), w, h, d,
         in.below(3) == 0, format, type, memory->pixels.data());
    break;
  }
  case 10:
    CALL(glCopyTexSubImage3D, target, level, in.size(), in.size(), in.size(), in.size(), in.size(), in.size(),
         in.size());
    break;
  case 0: {
    GLuint name = in.below(6);
    if (in.byte() & 1) glGenTextures(1, &name);
    glBindTexture(target, name);
    break;
  }
  case 1: {
    const GLuint name = in.below(6);
    glDeleteTextures(1, &name);
    break;
  }
  case 2: {
    // With client pixels: sizes within the buffers. Without: any size, which GL must refuse or
    // allocate (GL_OUT_OF_MEMORY when it cannot).
    const bool withData = in.byte() & 1;
    const GLsizei w = withData ? clientImageSide(in) : in.size();
    const GLsizei h = withData ? clientImageSide(in) : in.size();
    for (int i = 0; i < 64; ++i) memory->pixels[i] = in.byte();
    CALL(glTexImage2D, target, level, static_cast<GLint>(in.enumFrom(kEnums, kEnumCount)), w, h, in.below(3) == 0,
                 format, type, withData ? memory->pixels.data() : nullptr);
    break;
  }
  case 3:
    CALL(glTexImage1D, target, level, static_cast<GLint>(in.enumFrom(kEnums, kEnumCount)), clientImageSide(in),
                 in.below(3) == 0, format, type, memory->pixels.data());
    break;
  case 4:
    CALL(glTexSubImage2D, target, level, in.size(), in.size(), clientImageSide(in), clientImageSide(in), format, type,
                    memory->pixels.data());
    break;
  case 5:
    CALL(glCopyTexImage2D, target, level, in.enumFrom(kEnums, kEnumCount), in.size(), in.size(), in.size() % 70,
                     in.size() % 70, in.below(3) == 0);
    break;
  case 6: CALL(glCopyTexSubImage2D, target, level, in.size(), in.size(), in.size(), in.size(), in.size(), in.size()); break;
  case 7: {
    // glGetTexImage writes the level whole: only levels small enough for the buffer.
    GLint w = 0, h = 0;
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
    if (w <= kMaxTextureSideForRead && h <= kMaxTextureSideForRead)
      glGetTexImage(target, level, format, type, memory->textureReadback.data());
    break;
  }
  default: {
    const GLenum pname = in.enumFrom(kEnums, kEnumCount);
    float values[4];
    fill(in, values, 4);
    if (in.byte() & 1)
      glTexParameterfv(target, pname, values);
    else
      glTexParameteri(target, pname, static_cast<GLint>(in.enumFrom(kEnums, kEnumCount)));
    break;
  }
  }
}

void pixelCall(ByteReader &in) {
  const GLenum format = in.enumFrom(kEnums, kEnumCount);
  const GLenum type = in.enumFrom(kEnums, kEnumCount);
  switch (in.below(9)) {
  case 0: {
    const GLenum pname = in.enumFrom(kEnums, kEnumCount);
    glPixelStorei(pname, clampPixelStore(pname, in.size()));
    break;
  }
  case 1:
    for (int i = 0; i < 256; ++i) memory->pixels[i] = in.byte();
    CALL(glDrawPixels, clientImageSide(in), clientImageSide(in), format, type, memory->pixels.data());
    break;
  case 2: CALL(glReadPixels, in.size(), in.size(), clientImageSide(in), clientImageSide(in), format, type,
                       memory->readback.data());
    break;
  case 3: CALL(glCopyPixels, in.size(), in.size(), in.size(), in.size(), in.enumFrom(kEnums, kEnumCount)); break;
  case 4:
    CALL(glBitmap, clientImageSide(in), clientImageSide(in), in.real(), in.real(), in.real(), in.real(),
             memory->pixels.data());
    break;
  case 5: CALL(glPixelZoom, in.real(), in.real()); break;
  case 6: CALL(glPixelTransferf, in.enumFrom(kEnums, kEnumCount), in.real()); break;
  case 7: {
    float values[16];
    fill(in, values, 16);
    const int size = in.size();
    glPixelMapfv(in.enumFrom(kEnums, kEnumCount), size > 16 ? 16 : size, values);
    break;
  }
  default: CALL(glRasterPos4f, in.real(), in.real(), in.real(), in.byte() < 200 ? 1.0f : in.real()); break;
  }
}

void stateCall(ByteReader &in) {
  float v[16];
  switch (in.below(30)) {
  case 0: glEnable(in.enumFrom(kEnums, kEnumCount)); break;
  case 1: glDisable(in.enumFrom(kEnums, kEnumCount)); break;
  case 2: glMatrixMode(in.enumFrom(kEnums, kEnumCount)); break;
  case 3: glPushMatrix(); break;
  case 4: glPopMatrix(); break;
  case 5: CALL(glRotatef, in.real(), in.real(), in.real(), in.real()); break;
  case 6: CALL(glTranslatef, in.real(), in.real(), in.real()); break;
  case 7: CALL(glScalef, in.real(), in.real(), in.real()); break;
  case 8: CALL(glFrustum, in.real(), in.real(), in.real(), in.real(), in.real(), in.real()); break;
  case 9: CALL(glOrtho, in.real(), in.real(), in.real(), in.real(), in.real(), in.real()); break;
  case 10:
    fill(in, v, 16);
    glMultMatrixf(v);
    break;
  case 11: CALL(glViewport, in.size(), in.size(), in.size(), in.size()); break;
  case 12: CALL(glScissor, in.size(), in.size(), in.size(), in.size()); break;
  case 13: glClear(kClearMasks[in.below(7)]); break;
  case 14: CALL(glDepthRange, in.real(), in.real()); break;
  case 15:
    fill(in, v, 4);
    CALL(glLightfv, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount), v);
    break;
  case 16:
    fill(in, v, 4);
    CALL(glMaterialfv, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount), v);
    break;
  case 17:
    fill(in, v, 4);
    glLightModelfv(in.enumFrom(kEnums, kEnumCount), v);
    break;
  case 18:
    fill(in, v, 4);
    glFogfv(in.enumFrom(kEnums, kEnumCount), v);
    break;
  case 19:
    fill(in, v, 4);
    CALL(glTexEnvfv, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount), v);
    break;
  case 20:
    fill(in, v, 4);
    CALL(glTexGenfv, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount), v);
    break;
  case 21: CALL(glBlendFunc, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount)); break;
  case 22: CALL(glStencilFunc, in.enumFrom(kEnums, kEnumCount), in.size(), in.u32()); break;
  case 23:
    CALL(glStencilOp, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount));
    break;
  case 24: {
    const GLenum which = in.enumFrom(kEnums, kEnumCount);
    switch (in.below(10)) {
    case 0: glDepthFunc(which); break;
    case 1: glAlphaFunc(which, in.real()); break;
    case 2: glLogicOp(which); break;
    case 3: glCullFace(which); break;
    case 4: glFrontFace(which); break;
    case 5: glPolygonMode(which, in.enumFrom(kEnums, kEnumCount)); break;
    case 6: glShadeModel(which); break;
    case 7: glColorMaterial(which, in.enumFrom(kEnums, kEnumCount)); break;
    case 8: glHint(which, in.enumFrom(kEnums, kEnumCount)); break;
    default: glBlendEquation(which); break;
    }
    break;
  }
  case 25: {
    switch (in.below(6)) {
    case 0: glLineWidth(in.real()); break;
    case 1: glPointSize(in.real()); break;
    case 2: CALL(glPolygonOffset, in.real(), in.real()); break;
    case 3: CALL(glLineStipple, in.size(), in.u16()); break;
    case 4: CALL(glColorMask, in.byte() & 1, in.byte() & 1, in.byte() & 1, in.byte() & 1); break;
    default: glDepthMask(in.byte() & 1); break;
    }
    break;
  }
  case 26: {
    const GLdouble plane[4] = {in.real(), in.real(), in.real(), in.real()};
    glClipPlane(in.enumFrom(kEnums, kEnumCount), plane);
    break;
  }
  case 27:
    if (in.byte() & 1)
      glPushAttrib(kAttribMasks[in.below(11)]);
    else
      glPopAttrib();
    break;
  case 28:
    if (in.byte() & 1)
      glPushClientAttrib(in.byte() & 1 ? GL_CLIENT_ALL_ATTRIB_BITS : GL_CLIENT_VERTEX_ARRAY_BIT);
    else
      glPopClientAttrib();
    break;
  default: {
    // Queries write at most 16 values.
    const GLenum pname = in.enumFrom(kEnums, kEnumCount);
    GLdouble *out = memory->got.data();
    switch (in.below(5)) {
    case 0: glGetDoublev(pname, out); break;
    case 1: glGetFloatv(pname, reinterpret_cast<GLfloat *>(out)); break;
    case 2: glGetIntegerv(pname, reinterpret_cast<GLint *>(out)); break;
    case 3: glGetBooleanv(pname, reinterpret_cast<GLboolean *>(out)); break;
    default: glGetString(pname); break;
    }
    break;
  }
  }
}

// The lists a call may name: while list k is being compiled, only lists below k, so that lists
// call each other along a chain, never in a cycle (a list calling itself twice, 64 levels deep,
// is a GL program that runs 2^64 calls: correct, but endless).
int callableLists() {
  GLint compiling = 0;
  glGetIntegerv(GL_LIST_INDEX, &compiling);
  return compiling > 0 ? compiling : 8;
}

void listAndModeCall(ByteReader &in) {
  switch (in.below(12)) {
  case 0: CALL(glNewList, in.below(8), in.enumFrom(kEnums, kEnumCount)); break;
  case 1: glEndList(); break;
  case 2: glCallList(in.below(callableLists())); break;
  case 3: CALL(glDeleteLists, in.below(8), in.size()); break;
  case 4: glGenLists(in.size() % 8); break;
  case 5: {
    // At most 3 names a call keeps a chain of 7 lists below 3^7 calls.
    const int callable = callableLists();
    const GLuint base = in.below(3);
    std::array<GLubyte, 3> names{};
    for (auto &name : names) name = static_cast<GLubyte>(base < GLuint(callable) ? in.below(callable - int(base)) : 0);
    glListBase(base < GLuint(callable) ? base : 0);
    glCallLists(in.below(4), GL_UNSIGNED_BYTE, names.data());
    break;
  }
  case 6: {
    const GLenum mode = in.enumFrom(kEnums, kEnumCount);
    if (mode == GL_SELECT) glSelectBuffer(static_cast<GLsizei>(memory->select.size()), memory->select.data());
    if (mode == GL_FEEDBACK)
      glFeedbackBuffer(static_cast<GLsizei>(memory->feedback.size()), in.enumFrom(kEnums, kEnumCount),
                       memory->feedback.data());
    glRenderMode(mode);
    break;
  }
  case 7:
    switch (in.below(4)) {
    case 0: glInitNames(); break;
    case 1: glPushName(in.u32()); break;
    case 2: glPopName(); break;
    default: glLoadName(in.u32()); break;
    }
    break;
  case 8: CALL(glAccum, in.enumFrom(kEnums, kEnumCount), in.real()); break;
  case 9: {
    // Evaluators: orders at most 5 and 4 with strides 4 and 16 reach float 67 at most.
    float points[96];
    fill(in, points, 96);
    const GLint lowOrder = in.below(5);
    const GLint order = in.byte() < 250 ? lowOrder + 1 : lowOrder - 1;
    if (in.byte() & 1) {
      CALL(glMap1f, in.enumFrom(kEnums, kEnumCount), in.real(), in.real(), 4, order, points);
      CALL(glMapGrid1f, in.size(), in.real(), in.real());
      CALL(glEvalMesh1, in.enumFrom(kEnums, kEnumCount), in.size() % 30, in.size() % 30);
    } else {
      CALL(glMap2f, in.enumFrom(kEnums, kEnumCount), in.real(), in.real(), 4, order, in.real(), in.real(), 16,
              order > 4 ? 4 : order, points);
      CALL(glMapGrid2f, in.size() % 30, in.real(), in.real(), in.size() % 30, in.real(), in.real());
      CALL(glEvalMesh2, in.enumFrom(kEnums, kEnumCount), in.size() % 30, in.size() % 30, in.size() % 30,
                  in.size() % 30);
    }
    CALL(glEvalCoord2f, in.real(), in.real());
    break;
  }
  case 10:
    switch (in.below(6)) {
    case 0: glActiveTexture(in.enumFrom(kEnums, kEnumCount)); break;
    case 1: glClientActiveTexture(in.enumFrom(kEnums, kEnumCount)); break;
    case 2: glDrawBuffer(in.enumFrom(kEnums, kEnumCount)); break;
    case 3: glReadBuffer(in.enumFrom(kEnums, kEnumCount)); break;
    case 4: CALL(glPointParameterf, in.enumFrom(kEnums, kEnumCount), in.real()); break;
    default: {
      float values[3];
      fill(in, values, 3);
      glPointParameterfv(in.enumFrom(kEnums, kEnumCount), values);
      break;
    }
    }
    break;
  default: glGetError(); break;
  }
}

// Every client array points into the arrays buffer, so that enabling one the input never
// pointed anywhere reads that buffer rather than address 0 (which would be the program's fault in
// any GL): at the start, and after glassResetContext.
void pointArraysAtBuffer() {
  void *arrays = memory->arrays.data();
  glVertexPointer(4, GL_FLOAT, 0, arrays);
  glNormalPointer(GL_FLOAT, 0, arrays);
  glColorPointer(4, GL_FLOAT, 0, arrays);
  glIndexPointer(GL_FLOAT, 0, arrays);
  glTexCoordPointer(4, GL_FLOAT, 0, arrays);
  glEdgeFlagPointer(0, arrays);
  glFogCoordPointer(GL_FLOAT, 0, arrays);
  glSecondaryColorPointer(3, GL_FLOAT, 0, arrays);
}

void gluAndGlutCall(ByteReader &in) {
  // Tessellation counts and subdivisions stay small enough to draw quickly.
  const GLint slices = in.size() % 40;
  const GLint stacks = in.size() % 40;
  switch (in.below(9)) {
  case 0: {
    GLUquadric *quadric = gluNewQuadric();
    gluQuadricDrawStyle(quadric, in.enumFrom(kEnums, kEnumCount));
    gluQuadricNormals(quadric, in.enumFrom(kEnums, kEnumCount));
    gluQuadricOrientation(quadric, in.enumFrom(kEnums, kEnumCount));
    gluQuadricTexture(quadric, in.byte() & 1);
    switch (in.below(4)) {
    case 0: gluSphere(quadric, in.real(), slices, stacks); break;
    case 1: CALL(gluCylinder, quadric, in.real(), in.real(), in.real(), slices, stacks); break;
    case 2: CALL(gluDisk, quadric, in.real(), in.real(), slices, stacks); break;
    default: CALL(gluPartialDisk, quadric, in.real(), in.real(), slices, stacks, in.real(), in.real()); break;
    }
    gluDeleteQuadric(quadric);
    break;
  }
  case 1: CALL(gluPerspective, in.real(), in.real(), in.real(), in.real()); break;
  case 2: CALL(gluLookAt, in.real(), in.real(), in.real(), in.real(), in.real(), in.real(), in.real(), in.real(), in.real());
    break;
  case 3: {
    // The GLU mipmap builders and gluScaleImage read width x height (x depth, at most 4) client
    // pixels; gluScaleImage writes its result into the read-back buffer with the pack settings.
    for (int i = 0; i < 256; ++i) memory->pixels[i] = in.byte();
    const int which = in.byte();
    if (which & 1) {
      CALL(gluScaleImage, in.enumFrom(kEnums, kEnumCount), clientImageSide(in), clientImageSide(in),
           in.enumFrom(kEnums, kEnumCount), memory->pixels.data(), clientImageSide(in), clientImageSide(in),
           in.enumFrom(kEnums, kEnumCount), memory->readback.data());
      break;
    }
    const GLenum target = in.enumFrom(kEnums, kEnumCount);
    const auto internalFormat = static_cast<GLint>(in.enumFrom(kEnums, kEnumCount));
    if ((which & 6) == 2) {
      CALL(gluBuild1DMipmaps, target, internalFormat, clientImageSide(in), in.enumFrom(kEnums, kEnumCount),
           in.enumFrom(kEnums, kEnumCount), memory->pixels.data());
    } else if ((which & 6) == 4) {
      const GLsizei w = clientImageSide(in), h = clientImageSide(in);
      const int depth = in.size();
      CALL(gluBuild3DMipmaps, target, internalFormat, w, h, depth > 4 ? 4 : depth, in.enumFrom(kEnums, kEnumCount),
           in.enumFrom(kEnums, kEnumCount), memory->pixels.data());
    } else {
      CALL(gluBuild2DMipmaps, target, internalFormat, clientImageSide(in), clientImageSide(in),
           in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount), memory->pixels.data());
    }
    break;
  }
  case 4: {
    GLUtesselator *tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, reinterpret_cast<_GLUfuncptr>(tessBegin));
    gluTessCallback(tess, GLU_TESS_VERTEX, reinterpret_cast<_GLUfuncptr>(tessVertex));
    gluTessCallback(tess, GLU_TESS_END, reinterpret_cast<_GLUfuncptr>(tessEnd));
    if (in.byte() & 1) gluTessCallback(tess, GLU_TESS_COMBINE, reinterpret_cast<_GLUfuncptr>(tessCombine));
    CALL(gluTessProperty, tess, in.enumFrom(kEnums, kEnumCount), in.enumFrom(kEnums, kEnumCount));
    if (in.byte() & 1) CALL(gluTessNormal, tess, in.real(), in.real(), in.real());
    // Vertices on a small integer grid so that edges often cross, overlap and coincide.
    for (std::size_t i = 0; i < memory->tessVertices.size(); ++i)
      memory->tessVertices[i] = (i % 3 == 2) ? 0.0 : static_cast<double>(in.below(9)) - 4.0;
    if (in.byte() < 3) memory->tessVertices[in.below(64) * 3] = std::numeric_limits<double>::quiet_NaN();
    gluTessBeginPolygon(tess, nullptr);
    const int contours = in.below(4);
    int next = 0;
    for (int c = 0; c < contours; ++c) {
      gluTessBeginContour(tess);
      const int n = in.below(12);
      for (int i = 0; i < n && next < 64; ++i, ++next)
        gluTessVertex(tess, &memory->tessVertices[next * 3], &memory->tessVertices[next * 3]);
      gluTessEndContour(tess);
    }
    gluTessEndPolygon(tess);
    gluDeleteTess(tess);
    break;
  }
  case 5:
    if (in.byte() & 1)
      glutSolidSphere(in.real(), slices, stacks);
    else
      CALL(glutWireTorus, in.real(), in.real(), slices, stacks);
    break;
  case 6:
    switch (in.below(4)) {
    case 0: glutSolidTeapot(in.real()); break;
    case 1: CALL(glutSolidCone, in.real(), in.real(), slices, stacks); break;
    case 2: {
      GLdouble offset[3] = {in.real(), in.real(), in.real()};
      CALL(glutSolidSierpinskiSponge, in.below(6), offset, in.real());
      break;
    }
    default: glutWireCube(in.real()); break;
    }
    break;
  case 7: {
    // A swap, one or two colour buffers, with or without alpha bitplanes (chosen by what is
    // left of the input, so that no byte is taken), then the context back in its initial state
    // (glassResetContext), lists, textures and pixels kept, even between glBegin and glEnd; its
    // arrays point into the buffer again.
    GlassContext *current = glassGetCurrentContext();
    glassSwapBuffers(current);
    glassSetDoubleBuffered(current, static_cast<int>(in.size() & 1));
    glassSetAlphaBitplanes(current, static_cast<int>((in.size() >> 1) & 1));
    glassResetContext(current);
    pointArraysAtBuffer();
    break;
  }
  default: {
    // A second context: switch to it, draw, switch back; creation refuses bad sizes.
    GlassContext *current = glassGetCurrentContext();
    GlassContext *other = CALL(glassCreateContext, in.size() % 70, in.size() % 70);
    if (other != nullptr && glassMakeCurrent(other)) {
      glClear(GL_COLOR_BUFFER_BIT);
      drawImmediate(in);
    }
    glassMakeCurrent(current);
    glassDestroyContext(other);
    break;
  }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  Memory buffers;
  buffers.textureReadback.resize(kMaxTextureSideForRead * kMaxTextureSideForRead * 4 * 8);
  memory = &buffers;
  ByteReader in(data, size);
  GlassContext *context = glassCreateContext(48, 40);
  if (context == nullptr || !glassMakeCurrent(context)) return 0;
  pointArraysAtBuffer();
  // A bound on the calls per input keeps each run short.
  for (int calls = 0; calls < 400 && !in.done(); ++calls) {
    switch (in.below(10)) {
    case 0:
    case 1: drawImmediate(in); break;
    case 2: setArrays(in); break;
    case 3: drawArrays(in); break;
    case 4: textureCall(in); break;
    case 5: pixelCall(in); break;
    case 6:
    case 7: stateCall(in); break;
    case 8: listAndModeCall(in); break;
    default: gluAndGlutCall(in); break;
    }
  }
  glFinish();
  glassMakeCurrent(nullptr);
  glassDestroyContext(context);
  memory = nullptr;
  return 0;
}
