// Colours for a cloud of points read from a file (homework 3), so that a student sees its
// self-similar parts in `glass ifs3d view`. A chaos-game cloud knows which map made each point;
// a file's cloud does not, so:
//  - with maps known (a .ifs3 file given beside the cloud), each point takes the colour of the
//    map whose image of the cloud passes nearest to it: the cloud splits into the four parts
//    f_i(P) the collage theorem speaks of, and a point that no image comes near (noise, or a
//    part a wrong map misses) stays grey, which shows where the maps do not explain the cloud;
//  - without maps, a colour ramp over the height (y, the window's up): each part is a turned,
//    shrunk copy of the whole, so it repeats the whole's bands of colour in its own direction.
#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "glass/geometry/affine3d.h"

namespace glass::course {

inline constexpr int kUnexplainedPoint = -1;

// For each point, the index of the map whose image of the cloud lies nearest to it, or
// kUnexplainedPoint when that image is farther than kUnexplainedFactor times the cloud's spacing
// (the median distance between a point and its nearest neighbour). The images are of at most `imagePoints` points of the cloud (every n-th point);
// deterministic. Empty when there are no maps or no points.
inline constexpr double kUnexplainedFactor = 6.0;
std::vector<int> cloudPartsByMaps(std::span<const glm::dvec3> cloud, std::span<const geometry::Affine3> maps,
                                  std::size_t imagePoints = 60000);

// The ramp at t in [0, 1] (clamped): blue, cyan, green, yellow, orange-red, each bright enough to
// stand out against the window's dark background.
glm::vec3 heightRampColor(double t);

// Each point's colour on the ramp, t the point's height (y) between the cloud's lowest and
// highest point (0.5 for all when the cloud is flat).
std::vector<glm::vec3> heightColors(std::span<const glm::dvec3> cloud);

}  // namespace glass::course
