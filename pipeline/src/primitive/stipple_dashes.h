// Line stipple (spec 3.4.2) for antialiased lines, as Mesa's draw module applies it before its
// smooth-line stage: the segment is cut into the dashes the pattern turns on, and each dash is
// drawn as a smooth segment of its own (with its own rounded-off ends).
//
// Step i (0 <= i < ceil(L), L the segment's Euclidean length in pixels) is on when bit
// floor((counter + i) / factor) mod 16 of the pattern is set; a run of on steps from i0 to i1
// becomes the dash from t = i0 / L to t = i1 / L (the last one to t = 1). The counter then
// advances by ceil(L), carrying the pattern on along a strip.
#pragma once

#include <functional>

namespace glass::gl {

// Calls dash(t0, t1) for each dash of a segment of the given length; returns the counter after
// it. factor >= 1.
int forEachStippleDash(float length, int counter, unsigned short pattern, int factor,
                       const std::function<void(float, float)>& dash);

}  // namespace glass::gl
