// The interface between the pipeline and the fog stage (spec 3.10). The pipeline calls these;
// the fog stage implements them in fragment/ (fog_hooks.cpp).
#pragma once

#include <GL/gl.h>

#include "glass/raster/fragment.h"

namespace glass::gl {

struct Context;
struct StateValue;

// glEnable/glDisable/glIsEnabled of GL_FOG and GL_COLOR_SUM (whose attribute group is the fog's).
// False when cap is neither.
bool setFogCapability(Context& ctx, GLenum cap, bool enabled);
bool getFogCapability(const Context& ctx, GLenum cap, bool& enabled);
// glGet of fog state (GL_FOG_MODE, GL_FOG_COLOR, ...). False when pname is not fog state.
bool queryFogState(const Context& ctx, GLenum pname, StateValue& value);

bool fogEnabled(const Context& ctx);

// Per vertex, when fog is enabled: the value interpolated in varying slot 8 (spec 3.10: the eye
// distance c, which may be approximated by |z_e|). vertexFogCoord is the vertex's glFogCoord
// value, used with GL_FOG_COORDINATE as the source.
float fogCoordinate(const Context& ctx, const float eyePosition[4], float vertexFogCoord);

// The fog factor f (spec 3.10) for the eye distance c, clamped to [0, 1].
struct FogState;
float fogFactor(const FogState& fog, float c);

// Per fragment, after texturing and colour sum: blends color towards the fog colour. The
// fragment's interpolated fog coordinate is fragment.varyings[8]. `fog` is the draw's copy of
// the fog state (FragmentProcessor::prepare), so that queued draws keep theirs.
void applyFog(const FogState& fog, const raster::Fragment& fragment, float color[4]);

}  // namespace glass::gl
