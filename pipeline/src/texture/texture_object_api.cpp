// Texture objects (OpenGL 1.5 specification, section 3.8.12): glGenTextures, glDeleteTextures,
// glBindTexture, glIsTexture, glAreTexturesResident, glPrioritizeTextures.
#include <GL/gl.h>

#include <algorithm>
#include <vector>

#include "core/context.h"
#include "core/errors.h"
#include "lists/command_recording.h"

namespace glass::gl {
namespace {

void bindTexture(Context& ctx, GLenum target, GLuint name) {
  if (rejectInsideBeginEnd(ctx)) return;
  TextureState& t = ctx.texture;
  TextureUnit& u = t.unit();
  TextureObject** binding = target == GL_TEXTURE_1D         ? &u.bound1D
                            : target == GL_TEXTURE_2D       ? &u.bound2D
                            : target == GL_TEXTURE_3D       ? &u.bound3D
                            : target == GL_TEXTURE_CUBE_MAP ? &u.boundCube
                                                            : nullptr;
  if (binding == nullptr) return recordError(ctx, GL_INVALID_ENUM);
  if (name == 0) {
    *binding = target == GL_TEXTURE_1D   ? &t.default1D
               : target == GL_TEXTURE_2D ? &t.default2D
               : target == GL_TEXTURE_3D ? &t.default3D
                                         : &t.defaultCube;
    return;
  }
  const std::shared_ptr<TextureObject> texture = t.names->findOrCreate(name, target);
  if (texture->target != target) return recordError(ctx, GL_INVALID_OPERATION);
  *binding = texture.get();
  t.holdBindings();
}

void deleteTextures(Context& ctx, const std::vector<GLuint>& names) {
  TextureState& t = ctx.texture;
  for (GLuint name : names) {
    if (name == 0) continue;
    const std::shared_ptr<TextureObject> removed = t.names->remove(name);
    if (!removed) continue;
    // Spec 3.8.12: deleting a bound texture binds the default texture in its place, in every
    // texture unit it is bound to (of this context: texture_names.h says what other contexts see).
    for (TextureUnit& u : t.units) {
      if (u.bound1D == removed.get()) u.bound1D = &t.default1D;
      if (u.bound2D == removed.get()) u.bound2D = &t.default2D;
      if (u.bound3D == removed.get()) u.bound3D = &t.default3D;
      if (u.boundCube == removed.get()) u.boundCube = &t.defaultCube;
    }
  }
  t.holdBindings();
}

}  // namespace
}  // namespace glass::gl

using glass::gl::Context;

void GLAPIENTRY glGenTextures(GLsizei n, GLuint* textures) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (n < 0) return glass::gl::recordError(ctx, GL_INVALID_VALUE);
    ctx.texture.names->generate(n, textures);
  });
}

void GLAPIENTRY glDeleteTextures(GLsizei n, const GLuint* textures) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (n < 0) return glass::gl::recordError(ctx, GL_INVALID_VALUE);
    glass::gl::deleteTextures(ctx, std::vector<GLuint>(textures, textures + n));
  });
}

void GLAPIENTRY glBindTexture(GLenum target, GLuint texture) {
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::bindTexture(ctx, target, texture); });
}

GLboolean GLAPIENTRY glIsTexture(GLuint texture) {
  return glass::gl::queryNow(GLboolean(GL_FALSE), [=](Context& ctx) -> GLboolean {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return GL_FALSE;
    return ctx.texture.names->isTexture(texture) ? GL_TRUE : GL_FALSE;
  });
}

GLboolean GLAPIENTRY glAreTexturesResident(GLsizei n, const GLuint* textures, GLboolean* residences) {
  return glass::gl::queryNow(GLboolean(GL_FALSE), [=](Context& ctx) -> GLboolean {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return GL_FALSE;
    if (n < 0) {
      glass::gl::recordError(ctx, GL_INVALID_VALUE);
      return GL_FALSE;
    }
    for (GLsizei i = 0; i < n; ++i) {
      if (!ctx.texture.names->isTexture(textures[i])) {
        glass::gl::recordError(ctx, GL_INVALID_VALUE);
        return GL_FALSE;
      }
    }
    // Every texture lives in memory the renderer reads directly: all are resident, and the
    // specification then leaves residences untouched.
    (void)residences;
    return GL_TRUE;
  });
}

void GLAPIENTRY glPrioritizeTextures(GLsizei n, const GLuint* textures, const GLclampf* priorities) {
  if (n < 0) {
    glass::gl::compileOrExecute([](Context& ctx) {
      if (glass::gl::rejectInsideBeginEnd(ctx)) return;
      glass::gl::recordError(ctx, GL_INVALID_VALUE);
    });
    return;
  }
  std::vector<GLuint> names(textures, textures + n);
  std::vector<GLclampf> values(priorities, priorities + n);
  glass::gl::compileOrExecute([names, values](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    for (size_t i = 0; i < names.size(); ++i) {
      if (const auto t = ctx.texture.names->find(names[i]))
        t->params.priority = std::clamp(values[i], 0.0f, 1.0f);
    }
  });
}
