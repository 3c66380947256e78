// The two judgements the collage path of homework 3's fit (ifs3d_fit.h, step 6) rests on, when
// several maps are wrong at once and the search goes on by the collage distance rather than by
// the attractor: which maps are wrong (a right map's image lies in the cloud whatever the other
// maps do, a wrong one's falls partly out of it), and whether a set of maps may be ranked by the
// collage distance at all (Barnsley's collage theorem bounds the attractor's distance to the
// cloud by collage / (1 - s), s the maps' largest stretch, so the bound says nothing when a map
// swells towards s = 1, and a map shrunk to a point covers nothing).
#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "glass/geometry/affine3d.h"
#include "glass/geometry/kd_tree.h"

namespace glass::course {

// The largest stretches the path accepts: the course's maps have ratios 0.3 to 0.6, stretched or
// shrunk by up to a quarter along an axis (glass/course/ifs3d_random.h), with room on both sides.
inline constexpr double kCollagePathStretches[2] = {0.15, 0.85};

// Whether every map's largest singular value lies within kCollagePathStretches.
bool stretchesWithinCollagePath(std::span<const geometry::Affine3> maps);

// The maps ordered by how far their images of `source` fall from the cloud (the mean distance to
// its nearest point, the worst `trim` share left out), farthest first.
std::vector<std::size_t> mapsByInclusion(std::span<const geometry::Affine3> maps, std::span<const glm::dvec3> source,
                                         const geometry::KdTree3& cloudTree, double trim);

}  // namespace glass::course
