// The fast-path switch (core/fast_paths.h).
#include "core/fast_paths.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace glass::gl {
namespace {

// ScopedFastPaths's choice: 0 or 1, or -1 when the environment decides.
std::atomic<int> forcedFastPaths{-1};

}  // namespace

bool fastPathsEnabled() {
  const int forced = forcedFastPaths.load(std::memory_order_relaxed);
  if (forced >= 0) return forced != 0;
  // Read once: the choice holds for the life of the process, so that a draw never mixes paths.
  static const bool enabled = [] {
    const char* text = std::getenv("GLASS_FAST_PATHS");
    return text == nullptr || std::strcmp(text, "0") != 0;
  }();
  return enabled;
}

ScopedFastPaths::ScopedFastPaths(bool enabled)
    : previous_(forcedFastPaths.exchange(enabled ? 1 : 0, std::memory_order_relaxed)) {}

ScopedFastPaths::~ScopedFastPaths() { forcedFastPaths.store(previous_, std::memory_order_relaxed); }

}  // namespace glass::gl
