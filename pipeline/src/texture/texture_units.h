// Texture units (OpenGL 1.3, spec 2.7, 2.8, 2.10.2, 3.8.17): glass has eight texture units,
// GL_TEXTURE0 .. GL_TEXTURE7, as Mesa's llvmpipe reports for GL_MAX_TEXTURE_UNITS. Each unit has
// its own enables, bindings, texture environment, texgen, texture matrix stack, current texture
// coordinates and texture coordinate array; glActiveTexture selects the unit that the texture
// commands, glEnable(GL_TEXTURE_*) and glMatrixMode(GL_TEXTURE) address, glClientActiveTexture the
// unit of glTexCoordPointer and GL_TEXTURE_COORD_ARRAY. A unit at or above GL_MAX_TEXTURE_UNITS is
// GL_INVALID_ENUM for both (spec 2.7 and 2.8); glMultiTexCoord drops the coordinates of such a
// unit without an error, as Mesa does (the specification lists no error for it).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

inline constexpr int kTextureUnitCount = 8;

// True for GL_TEXTURE0 .. GL_TEXTURE0 + kTextureUnitCount - 1.
inline bool isTextureUnit(GLenum unit) {
  return unit >= GL_TEXTURE0 && unit < GL_TEXTURE0 + kTextureUnitCount;
}

// glGet of GL_ACTIVE_TEXTURE, GL_CLIENT_ACTIVE_TEXTURE and GL_MAX_TEXTURE_UNITS. False when
// pname is none of them.
bool queryTextureUnitState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
