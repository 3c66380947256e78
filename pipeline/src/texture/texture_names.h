// The named texture objects of a context (OpenGL 1.5, section 3.8.12), which OSMesa contexts
// created with a sharelist share (docs/osmesa.md). Every use of the table locks it, so contexts
// current on different threads may generate, bind, delete and look up names at the same time.
//
// Objects are held by shared_ptr: a texture deleted in one context stays alive in another that
// still has it bound (TextureState::holdBindings), until that context binds something else.
// OpenGL 1.x leaves deletion of a shared object bound elsewhere to the implementation; this is
// the rule OpenGL 3.2 later wrote down (appendix D.1.2).
#pragma once

#include <GL/gl.h>

#include <memory>
#include <mutex>
#include <unordered_map>
#include <unordered_set>

#include "texture/texture_object.h"

namespace glass::gl {

class TextureNames {
 public:
  // The texture named `name`, or null when the name is not a texture (0 never is).
  std::shared_ptr<TextureObject> find(GLuint name) const;
  // The texture named `name`, made a texture of `target` if it was not one yet (spec 3.8.12: a
  // name becomes a texture when first bound). Throws std::bad_alloc.
  std::shared_ptr<TextureObject> findOrCreate(GLuint name, GLenum target);
  bool isTexture(GLuint name) const;
  // glGenTextures: n names neither textures nor reserved, reserved until bound or deleted.
  void generate(GLsizei n, GLuint* names);
  // glDeleteTextures of one name: frees it and returns the texture it named, or null.
  std::shared_ptr<TextureObject> remove(GLuint name);

 private:
  mutable std::mutex mutex_;
  std::unordered_map<GLuint, std::shared_ptr<TextureObject>> objects_;
  // Names returned by glGenTextures and not yet bound: in use, but not yet textures (glIsTexture
  // is false for them, spec 3.8.12).
  std::unordered_set<GLuint> reserved_;
  GLuint next_ = 1;  // where glGenTextures starts looking
};

}  // namespace glass::gl
