// Homework 2's pictures: an IFS drawn with GL into the current context, either to a depth n by
// recursion on the modelview matrix stack (the guide's Listing 4, generalised to any maps) or by
// the chaos game (the guide's "probability approach"), each map's part in its own colour, in the
// window of the IFS fitted to the picture's shape by Listing 5's resizeWindow.
#pragma once

#include <cstdint>
#include <string>

#include "glass/geometry/ifs.h"

namespace glass::course {

struct IfsPicture {
  int width = 800, height = 800;
  enum class Method { Depth, ChaosGame };
  Method method = Method::Depth;
  int depth = 6;
  std::uint64_t points = 1'000'000;
  std::uint64_t seed = 1;
};

// A depth for a picture of `pixels` across: the depth at which the copies that shrink slowest
// (by the largest stretch factor of any map) are still three pixels across or more, within `budget` base
// copies and at most 30 levels (GL guarantees a modelview stack of 32 matrices). Maps that
// shrink slowly, like the fern's, stop at the budget: the chaos game suits them better.
int defaultIfsDepth(const geometry::IteratedFunctionSystem& ifs, int pixels, std::uint64_t budget = 1u << 18);

// Empty when the picture can be drawn, else why not (depth beyond the limits, bad probabilities).
std::string checkIfsPicture(const geometry::IteratedFunctionSystem& ifs, const IfsPicture& picture);

// Clears and draws; the context must be picture.width x picture.height.
void drawIfsPicture(const geometry::IteratedFunctionSystem& ifs, const IfsPicture& picture);

}  // namespace glass::course
