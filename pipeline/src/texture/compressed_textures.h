// Compressed textures (OpenGL 1.3): glass has no specific compressed format
// (api/compressed_texture_api.cpp says what the commands do).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

// glGet of GL_NUM_COMPRESSED_TEXTURE_FORMATS (0) and GL_COMPRESSED_TEXTURE_FORMATS (no values).
// False when pname is neither.
bool queryCompressedTextureState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
