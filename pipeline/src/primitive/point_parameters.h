// Point parameters (OpenGL 1.4, spec 3.3): a point's size shrinks with its distance d from the
// eye,
//   derived size = clamp(size * sqrt(1 / (a + b d + c d^2)), GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX)
// with (a, b, c) = GL_POINT_DISTANCE_ATTENUATION, (1, 0, 0) by default, which leaves the size as
// it is. GL_POINT_FADE_THRESHOLD_SIZE matters only with multisampling, which glass's framebuffer
// does not have, so it is kept and queried only (as in Mesa without multisampling).
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct RasterState;
struct StateValue;

// glGet of the four point parameters. False when pname is none of them.
bool queryPointParameterState(const Context& ctx, GLenum pname, StateValue& value);

// Whether the point parameters change any point's size (attenuation or clamping other than the
// defaults).
bool pointSizeAttenuated(const RasterState& r);

// The derived size of a point at eye distance d.
float derivedPointSize(const RasterState& r, float eyeDistance);

}  // namespace glass::gl
