// Placeholder fog hooks: replaced by the fog stage. Fog is off.
#include "fragment/fog_hooks.h"

#include <cmath>

#include "core/context.h"

namespace glass::gl {

bool setFogCapability(Context&, GLenum, bool) { return false; }
bool getFogCapability(const Context&, GLenum, bool&) { return false; }
bool queryFogState(const Context&, GLenum, StateValue&) { return false; }
bool fogEnabled(const Context&) { return false; }
float fogCoordinate(const Context&, const float eyePosition[4]) { return std::fabs(eyePosition[2]); }
void applyFog(const Context&, const raster::Fragment&, float*) {}

}  // namespace glass::gl
