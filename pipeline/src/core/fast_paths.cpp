#include "core/fast_paths.h"

#include <cstdlib>
#include <cstring>

namespace glass::gl {

bool fastPathsEnabled() {
  // Read once: the choice holds for the life of the process, so that a draw never mixes paths.
  static const bool enabled = [] {
    const char* text = std::getenv("GLASS_FAST_PATHS");
    return text == nullptr || std::strcmp(text, "0") != 0;
  }();
  return enabled;
}

const char* simdTargetName() { return "scalar"; }

}  // namespace glass::gl
