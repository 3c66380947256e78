// Random 3D IFS and their clouds, for checking `glass ifs3d fit` on systems nobody chose by hand
// (the fit battery, tools/benchmark/ifs3d_fit_battery.cpp, and the unit tests). Each system has
// four contractive maps L_i x + t_i with L_i = R_i diag(s_i), where R_i turns by a random angle
// about a random (oblique) axis and the scales s_i are a similarity ratio in 0.3..0.6, made
// uneven (by up to +-25% per axis) for about half of the maps; exactly one map reflects (one
// negative scale). Each map sends the unit cube into the unit cube at a random place, so parts
// often overlap.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "glass/geometry/affine3d.h"
#include "glass/geometry/ifs3d.h"

namespace glass::course {

geometry::IteratedFunctionSystem3 randomIfs3(std::uint64_t seed);

// `count` chaos-game points of the attractor (seeded), a share `noise` of them replaced by
// points uniform in the unit cube.
std::vector<glm::dvec3> ifs3Cloud(const geometry::IteratedFunctionSystem3& ifs, std::size_t count, double noise,
                                  std::uint64_t seed);

// The largest difference of matrix entries between `truth` and `found` under the best pairing of
// their maps (the order of maps is arbitrary); infinity when the counts differ.
double ifs3MapError(const std::vector<geometry::Affine3>& truth, const std::vector<geometry::Affine3>& found);

}  // namespace glass::course
