// Vertex arrays (spec 2.8): client array state, glArrayElement, glDrawArrays, glDrawElements.
// Client state is never compiled into display lists; the draws are, with their data read at
// compile time.
#include <GL/gl.h>

#include <vector>

#include "core/context.h"
#include "lists/command_recording.h"
#include "select/render_mode_query.h"
#include "vertex/array_draw.h"
#include "vertex/primitive_assembly.h"
#include "vertex/vertex_arrays.h"

using glass::gl::ClientArray;
using glass::gl::Context;
using glass::gl::executeNow;
using glass::gl::recordError;

namespace {

ClientArray* clientArray(Context& ctx, GLenum array) {
  switch (array) {
    case GL_VERTEX_ARRAY: return &ctx.arrays.vertex;
    case GL_COLOR_ARRAY: return &ctx.arrays.color;
    case GL_NORMAL_ARRAY: return &ctx.arrays.normal;
    case GL_TEXTURE_COORD_ARRAY: return &ctx.arrays.texCoord[ctx.arrays.clientActiveUnit];
    case GL_EDGE_FLAG_ARRAY: return &ctx.arrays.edgeFlag;
    case GL_INDEX_ARRAY: return &ctx.arrays.index;  // accepted, never drawn (core/color_index.h)
    case GL_FOG_COORDINATE_ARRAY: return &ctx.arrays.fogCoord;
    case GL_SECONDARY_COLOR_ARRAY: return &ctx.arrays.secondaryColor;
    default: return nullptr;
  }
}

// Client array commands are not allowed between glBegin and glEnd either (as in Mesa; spec 2.6.3
// lists the commands that are).
void setClientState(GLenum array, bool enabled) {
  executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    ClientArray* a = clientArray(ctx, array);
    if (!a) return recordError(ctx, GL_INVALID_ENUM);
    a->enabled = enabled;
  });
}

bool isOneOf(GLenum type, std::initializer_list<GLenum> types) {
  for (GLenum t : types) {
    if (t == type) return true;
  }
  return false;
}

// The errors of the *Pointer commands (spec 2.8): a size or stride out of range is
// GL_INVALID_VALUE, a type the array does not take GL_INVALID_ENUM.
void setPointer(GLenum array, GLint size, bool sizeValid, GLenum type, bool typeValid,
                GLsizei stride, const GLvoid* pointer) {
  executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (!sizeValid || stride < 0) return recordError(ctx, GL_INVALID_VALUE);
    if (!typeValid) return recordError(ctx, GL_INVALID_ENUM);
    ClientArray* a = clientArray(ctx, array);
    a->size = size;
    a->type = type;
    a->stride = stride;
    a->pointer = pointer;
  });
}

bool rejectDraw(Context& ctx, GLenum mode, GLsizei count) {
  if (!glass::gl::isPrimitiveMode(mode)) {
    recordError(ctx, GL_INVALID_ENUM);
    return true;
  }
  if (count < 0) {
    recordError(ctx, GL_INVALID_VALUE);
    return true;
  }
  return glass::gl::rejectInsideBeginEnd(ctx);
}

}  // namespace

extern "C" {

void glEnableClientState(GLenum array) { setClientState(array, true); }
void glDisableClientState(GLenum array) { setClientState(array, false); }

void glVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  setPointer(GL_VERTEX_ARRAY, size, size >= 2 && size <= 4, type,
             isOneOf(type, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}), stride, ptr);
}

void glColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  setPointer(GL_COLOR_ARRAY, size, size == 3 || size == 4, type,
             isOneOf(type, {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT,
                            GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE}),
             stride, ptr);
}

void glNormalPointer(GLenum type, GLsizei stride, const GLvoid* ptr) {
  setPointer(GL_NORMAL_ARRAY, 3, true, type,
             isOneOf(type, {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}), stride, ptr);
}

void glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  setPointer(GL_TEXTURE_COORD_ARRAY, size, size >= 1 && size <= 4, type,
             isOneOf(type, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}), stride, ptr);
}

void glEdgeFlagPointer(GLsizei stride, const GLvoid* ptr) {
  setPointer(GL_EDGE_FLAG_ARRAY, 1, true, GL_UNSIGNED_BYTE, true, stride, ptr);
}

void glGetPointerv(GLenum pname, GLvoid** params) {
  executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const ClientArray* a = nullptr;
    switch (pname) {
      case GL_VERTEX_ARRAY_POINTER: a = &ctx.arrays.vertex; break;
      case GL_COLOR_ARRAY_POINTER: a = &ctx.arrays.color; break;
      case GL_NORMAL_ARRAY_POINTER: a = &ctx.arrays.normal; break;
      case GL_TEXTURE_COORD_ARRAY_POINTER:
        a = &ctx.arrays.texCoord[ctx.arrays.clientActiveUnit];
        break;
      case GL_EDGE_FLAG_ARRAY_POINTER: a = &ctx.arrays.edgeFlag; break;
      case GL_INDEX_ARRAY_POINTER: a = &ctx.arrays.index; break;
      case GL_FOG_COORDINATE_ARRAY_POINTER: a = &ctx.arrays.fogCoord; break;
      case GL_SECONDARY_COLOR_ARRAY_POINTER: a = &ctx.arrays.secondaryColor; break;
      default: {
        void* buffer = nullptr;  // the selection and feedback buffers (select/)
        if (!glass::gl::queryRenderModePointer(ctx, pname, &buffer)) return recordError(ctx, GL_INVALID_ENUM);
        if (params) *params = buffer;
        return;
      }
    }
    if (params) *params = const_cast<GLvoid*>(a->pointer);
  });
}

void glArrayElement(GLint i) {
  executeNow([=](Context& ctx) { glass::gl::arrayElement(ctx, i); });
}

void glDrawArrays(GLenum mode, GLint first, GLsizei count) {
  executeNow([=](Context& ctx) {
    if (rejectDraw(ctx, mode, count)) return;
    glass::gl::drawArrayElements(ctx, mode, nullptr, first, count);
  });
}

void glDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid* indices) {
  executeNow([=](Context& ctx) {
    if (!glass::gl::isPrimitiveMode(mode) ||
        !isOneOf(type, {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT})) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    if (rejectDraw(ctx, mode, count) || !indices) return;
    std::vector<int> list(static_cast<size_t>(count));
    for (GLsizei i = 0; i < count; ++i) {
      switch (type) {
        case GL_UNSIGNED_BYTE: list[i] = static_cast<const GLubyte*>(indices)[i]; break;
        case GL_UNSIGNED_SHORT: list[i] = static_cast<const GLushort*>(indices)[i]; break;
        default: list[i] = static_cast<int>(static_cast<const GLuint*>(indices)[i]); break;
      }
    }
    glass::gl::drawArrayElements(ctx, mode, list.data(), 0, count);
  });
}

}  // extern "C"
