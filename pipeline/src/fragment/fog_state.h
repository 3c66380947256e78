// Fog state (glFog). Placeholder until the fog stage lands: replaced by the fog stage.
#pragma once

namespace glass {

struct FogState {};

}  // namespace glass
