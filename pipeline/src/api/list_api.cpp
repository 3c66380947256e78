// Display lists (spec 5.4): glGenLists, glNewList, glEndList, glCallList, glCallLists, glListBase,
// glDeleteLists, glIsList.
#include <GL/gl.h>

#include <cstring>
#include <vector>

#include "core/context.h"
#include "lists/command_recording.h"
#include "lists/list_execution.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::executeNow;
using glass::gl::queryNow;
using glass::gl::recordError;
using glass::gl::rejectInsideBeginEnd;

namespace {

// The list names of glCallLists' array (spec 5.4, table 5.7), before glListBase is added.
bool readListNames(GLsizei n, GLenum type, const GLvoid* lists, std::vector<GLuint>& names) {
  const auto* bytes = static_cast<const unsigned char*>(lists);
  names.resize(static_cast<size_t>(n));
  for (GLsizei i = 0; i < n; ++i) {
    GLuint name = 0;
    switch (type) {
      case GL_BYTE: name = static_cast<GLuint>(static_cast<GLint>(reinterpret_cast<const GLbyte*>(bytes)[i])); break;
      case GL_UNSIGNED_BYTE: name = bytes[i]; break;
      case GL_SHORT: { GLshort v; std::memcpy(&v, bytes + 2 * i, 2); name = static_cast<GLuint>(static_cast<GLint>(v)); break; }
      case GL_UNSIGNED_SHORT: { GLushort v; std::memcpy(&v, bytes + 2 * i, 2); name = v; break; }
      case GL_INT: { GLint v; std::memcpy(&v, bytes + 4 * i, 4); name = static_cast<GLuint>(v); break; }
      case GL_UNSIGNED_INT: { std::memcpy(&name, bytes + 4 * i, 4); break; }
      case GL_FLOAT: { GLfloat v; std::memcpy(&v, bytes + 4 * i, 4); name = static_cast<GLuint>(static_cast<long long>(v)); break; }
      // GL_n_BYTES: n unsigned bytes per name, most significant first.
      case GL_2_BYTES: name = (GLuint(bytes[2 * i]) << 8) | bytes[2 * i + 1]; break;
      case GL_3_BYTES:
        name = (GLuint(bytes[3 * i]) << 16) | (GLuint(bytes[3 * i + 1]) << 8) | bytes[3 * i + 2];
        break;
      case GL_4_BYTES:
        name = (GLuint(bytes[4 * i]) << 24) | (GLuint(bytes[4 * i + 1]) << 16) |
               (GLuint(bytes[4 * i + 2]) << 8) | bytes[4 * i + 3];
        break;
      default: return false;
    }
    names[i] = name;
  }
  return true;
}

bool isListNameType(GLenum type) {
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_INT:
    case GL_UNSIGNED_INT: case GL_FLOAT: case GL_2_BYTES: case GL_3_BYTES: case GL_4_BYTES:
      return true;
    default:
      return false;
  }
}

}  // namespace

extern "C" {

GLuint glGenLists(GLsizei range) {
  return queryNow(GLuint(0), [=](Context& ctx) -> GLuint {
    if (rejectInsideBeginEnd(ctx)) return 0;
    if (range < 0) {
      recordError(ctx, GL_INVALID_VALUE);
      return 0;
    }
    return range == 0 ? 0 : glass::gl::generateLists(ctx, range);
  });
}

void glNewList(GLuint list, GLenum mode) {
  executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (list == 0) return recordError(ctx, GL_INVALID_VALUE);
    if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return recordError(ctx, GL_INVALID_ENUM);
    if (ctx.lists.isCompiling()) return recordError(ctx, GL_INVALID_OPERATION);
    ctx.lists.compilingName = list;
    ctx.lists.compileMode = mode;
    ctx.lists.compiling = std::make_unique<glass::gl::DisplayList>();
  });
}

void glEndList(void) {
  executeNow([](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (!ctx.lists.isCompiling()) return recordError(ctx, GL_INVALID_OPERATION);
    // The new list replaces the old one of that name only now (spec 5.4).
    ctx.lists.lists->replace(ctx.lists.compilingName,
                             std::shared_ptr<const glass::gl::DisplayList>(std::move(ctx.lists.compiling)));
    ctx.lists.compilingName = 0;
  });
}

void glCallList(GLuint list) {
  compileOrExecute([=](Context& ctx) { glass::gl::callList(ctx, list); });
}

void glCallLists(GLsizei n, GLenum type, const GLvoid* lists) {
  executeNow([=](Context& ctx) {
    // Checked when the command is given: the names are read now, also when compiling.
    if (n < 0) return recordError(ctx, GL_INVALID_VALUE);
    if (!isListNameType(type)) return recordError(ctx, GL_INVALID_ENUM);
    if (n == 0 || !lists) return;
    std::vector<GLuint> names;
    readListNames(n, type, lists, names);
    glass::gl::compileOrExecuteOn(ctx, [names = std::move(names)](Context& c) {
      // glListBase as it is when the lists are called.
      for (GLuint name : names) glass::gl::callList(c, c.lists.listBase + name);
    });
  });
}

void glListBase(GLuint base) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    ctx.lists.listBase = base;
  });
}

void glDeleteLists(GLuint list, GLsizei range) {
  executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (range < 0) return recordError(ctx, GL_INVALID_VALUE);
    ctx.lists.lists->erase(list, static_cast<unsigned long long>(list) + static_cast<unsigned>(range));
  });
}

GLboolean glIsList(GLuint list) {
  return queryNow(GLboolean(GL_FALSE), [=](Context& ctx) -> GLboolean {
    if (rejectInsideBeginEnd(ctx)) return GL_FALSE;
    return ctx.lists.lists->contains(list) ? GL_TRUE : GL_FALSE;
  });
}

}  // extern "C"
