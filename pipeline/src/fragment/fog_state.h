// Fog state (glFog). Placeholder until the fog stage lands: replaced by the fog stage.
#pragma once

namespace glass::gl {

struct FogState {};

}  // namespace glass::gl
