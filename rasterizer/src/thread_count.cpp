#include "glass/raster/thread_count.h"

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace glass::raster {

int configuredThreadCount() {
  if (const char* text = std::getenv("GLASS_THREADS")) {
    char* end = nullptr;
    const long n = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && n >= 1 && n <= 256) return static_cast<int>(n);
  }
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace glass::raster
