// glEnable, glDisable and glIsEnabled (spec 2.x and 6.1.1). The pipeline's own capabilities are
// listed in capabilities.cpp; the lighting, fog and texturing stages answer for theirs through
// their hooks (setLightingCapability, ...), asked in turn.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

// Returns false when cap is not a capability glEnable accepts (GL_INVALID_ENUM).
bool setCapability(Context& ctx, GLenum cap, bool enabled);
// Returns false when cap is not a capability glIsEnabled accepts. Includes the client arrays
// (GL_VERTEX_ARRAY, ...), which glEnable does not accept.
bool getCapability(const Context& ctx, GLenum cap, bool& enabled);

}  // namespace glass::gl
