// glInterleavedArrays (OpenGL 1.5 specification, section 2.8, table 2.5): sets up the vertex,
// normal, colour and texture coordinate arrays for one of fourteen interleaved layouts, as if by
// the *Pointer and Enable/DisableClientState commands the specification lists. Client state:
// never compiled into display lists; like the other array commands, not allowed between glBegin
// and glEnd.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"

using glass::gl::ClientArray;
using glass::gl::Context;

namespace {

// One row of table 2.5. Offsets and the stride are in bytes: f = sizeof(GLfloat), c = 4 bytes
// of GL_UNSIGNED_BYTE colour (rounded up to a multiple of f, which it already is).
struct InterleavedLayout {
  GLenum format;
  int texCoordSize;     // st, 0: no texture coordinates
  int colorSize;        // sc, 0: no colour
  GLenum colorType;     // tc
  bool normal;          // en
  int vertexSize;       // sv
  int colorOffset, normalOffset, vertexOffset;  // pc, pn, pv
  int stride;           // s
};

constexpr int f = static_cast<int>(sizeof(GLfloat));
constexpr int c = 4;

constexpr InterleavedLayout kLayouts[] = {
    {GL_V2F, 0, 0, 0, false, 2, 0, 0, 0, 2 * f},
    {GL_V3F, 0, 0, 0, false, 3, 0, 0, 0, 3 * f},
    {GL_C4UB_V2F, 0, 4, GL_UNSIGNED_BYTE, false, 2, 0, 0, c, c + 2 * f},
    {GL_C4UB_V3F, 0, 4, GL_UNSIGNED_BYTE, false, 3, 0, 0, c, c + 3 * f},
    {GL_C3F_V3F, 0, 3, GL_FLOAT, false, 3, 0, 0, 3 * f, 6 * f},
    {GL_N3F_V3F, 0, 0, 0, true, 3, 0, 0, 3 * f, 6 * f},
    {GL_C4F_N3F_V3F, 0, 4, GL_FLOAT, true, 3, 0, 4 * f, 7 * f, 10 * f},
    {GL_T2F_V3F, 2, 0, 0, false, 3, 0, 0, 2 * f, 5 * f},
    {GL_T4F_V4F, 4, 0, 0, false, 4, 0, 0, 4 * f, 8 * f},
    {GL_T2F_C4UB_V3F, 2, 4, GL_UNSIGNED_BYTE, false, 3, 2 * f, 0, c + 2 * f, c + 5 * f},
    {GL_T2F_C3F_V3F, 2, 3, GL_FLOAT, false, 3, 2 * f, 0, 5 * f, 8 * f},
    {GL_T2F_N3F_V3F, 2, 0, 0, true, 3, 0, 2 * f, 5 * f, 8 * f},
    {GL_T2F_C4F_N3F_V3F, 2, 4, GL_FLOAT, true, 3, 2 * f, 6 * f, 9 * f, 12 * f},
    {GL_T4F_C4F_N3F_V4F, 4, 4, GL_FLOAT, true, 4, 4 * f, 8 * f, 11 * f, 15 * f},
};

void setArray(ClientArray& array, bool enabled, int size, GLenum type, int stride, const void* pointer) {
  array.enabled = enabled;
  if (!enabled) return;
  array.size = size;
  array.type = type;
  array.stride = stride;
  array.pointer = pointer;
}

}  // namespace

extern "C" {

void glInterleavedArrays(GLenum format, GLsizei stride, const GLvoid* pointer) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const InterleavedLayout* layout = nullptr;
    for (const InterleavedLayout& l : kLayouts) {
      if (l.format == format) layout = &l;
    }
    if (!layout) return glass::gl::recordError(ctx, GL_INVALID_ENUM);
    if (stride < 0) return glass::gl::recordError(ctx, GL_INVALID_VALUE);
    const int str = stride != 0 ? stride : layout->stride;
    const auto* p = static_cast<const unsigned char*>(pointer);
    glass::gl::ArrayState& a = ctx.arrays;
    // Spec 2.8: glInterleavedArrays disables the edge flag and colour index arrays.
    a.edgeFlag.enabled = false;
    a.index.enabled = false;
    // The texture coordinates go to the client active unit's array (spec 2.8).
    setArray(a.texCoord[a.clientActiveUnit], layout->texCoordSize > 0, layout->texCoordSize,
             GL_FLOAT, str, p);
    setArray(a.color, layout->colorSize > 0, layout->colorSize, layout->colorType, str,
             p + layout->colorOffset);
    setArray(a.normal, layout->normal, 3, GL_FLOAT, str, p + layout->normalOffset);
    setArray(a.vertex, true, layout->vertexSize, GL_FLOAT, str, p + layout->vertexOffset);
  });
}

}  // extern "C"
