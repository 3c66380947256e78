// Texture units (OpenGL 1.3, spec 2.7, 2.8, 3.8.17): glass has one texture unit, GL_TEXTURE0, so
// GL_MAX_TEXTURE_UNITS is 1. glActiveTexture and glClientActiveTexture accept GL_TEXTURE0 and set
// GL_INVALID_ENUM for every other unit (spec 2.7: the unit must be below GL_MAX_TEXTURE_UNITS);
// glMultiTexCoord(GL_TEXTURE0, ...) is glTexCoord, and the coordinates of the units glass lacks
// are dropped without an error, as Mesa drops those of units beyond its own count.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

inline constexpr int kTextureUnitCount = 1;

// True for GL_TEXTURE0 .. GL_TEXTURE0 + kTextureUnitCount - 1.
inline bool isTextureUnit(GLenum unit) {
  return unit >= GL_TEXTURE0 && unit < GL_TEXTURE0 + kTextureUnitCount;
}

// glGet of GL_ACTIVE_TEXTURE and GL_CLIENT_ACTIVE_TEXTURE (always GL_TEXTURE0). False when pname
// is neither.
bool queryTextureUnitState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
