#include "primitive/stipple_dashes.h"

#include <cmath>
#include <limits>

namespace glass::gl {

int forEachStippleDash(float length, int counter, unsigned short pattern, int factor,
                       const std::function<void(float, float)>& dash) {
  if (!std::isfinite(length) || !(length > 0.0f)) return counter;
  // Far more steps than any framebuffer has pixels would only burn time: beyond this the pattern
  // is taken as it stands at the last step.
  constexpr float kMaxSteps = 1 << 20;
  const int steps = static_cast<int>(std::ceil(std::fmin(length, kMaxSteps)));
  bool on = false;
  int start = 0;
  for (int i = 0; i < steps; ++i) {
    const bool bit = (pattern >> (((counter + i) / factor) & 15)) & 1u;
    if (bit == on) continue;
    if (on && start != i) dash(static_cast<float>(start) / length, static_cast<float>(i) / length);
    if (!on) start = i;
    on = bit;
  }
  if (on && static_cast<float>(start) < length) dash(static_cast<float>(start) / length, 1.0f);
  const long long next = static_cast<long long>(counter) + steps;
  return next > std::numeric_limits<int>::max() / 2 ? static_cast<int>(next % (16 * factor))
                                                     : static_cast<int>(next);
}

}  // namespace glass::gl
