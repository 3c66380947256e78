// The vertex attributes OpenGL 1.4 added (spec 2.7, 2.8): the fog coordinate (glFogCoord, used
// as fog's c when GL_FOG_COORDINATE_SOURCE is GL_FOG_COORDINATE, fragment/fog_hooks.cpp) and the
// secondary colour (glSecondaryColor, added to the primary colour without lighting when
// GL_COLOR_SUM is enabled, vertex/vertex_stage.cpp), with their client arrays.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

// glGet of GL_CURRENT_FOG_COORDINATE, GL_CURRENT_SECONDARY_COLOR and the two arrays' type, size
// and stride. False when pname is none of these.
bool querySecondaryAttributeState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
