// The map a fit of homework 3 misses, found from what the others leave uncovered (ifs3d_fit.h).
// When a part of the attractor is small and lies mostly inside larger parts that overlap, the
// splits and the whole-cloud search cover it poorly: the fit ends with two maps on one part and
// the small part's points, the few not inside the others, left far from every image. Those points
// (the residual) must lie in the missing map's image, and its image must lie in the cloud:
//    f(P) in P      and      f^-1(R) in P.
// Both conditions are read off the distance grid of the cloud (ifs3d_distance_grid.h): candidate
// maps x -> c + r Q (x - mean) over ratios, orientations (with reflections) and centres are
// scored by how far the images of spread cloud points, and the pre-images of spread residual
// points, fall from the cloud; the best are improved by hill climbing on the same score.
#pragma once

#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "glass/course/ifs3d_distance_grid.h"
#include "glass/geometry/affine3d.h"

namespace glass::course {

// The points of `points` farther than `limit` from every image f_i(source): the part of the cloud
// the maps leave uncovered. With the whole cloud as source, right maps leave every point within a
// few point spacings of an image.
std::vector<glm::dvec3> uncoveredPoints(std::span<const geometry::Affine3> maps, std::span<const glm::dvec3> source,
                                        std::span<const glm::dvec3> points, double limit);

// The points split into clusters, points closer than `link` joined (single linkage), largest
// first. The uncovered points of a fit that misses a map are its part's uncovered piece plus thin
// slivers all over where the other maps are slightly off; the search below needs the piece alone.
std::vector<std::vector<glm::dvec3>> residualClusters(std::span<const glm::dvec3> points, double link);

// The maps ordered by how much of `points` each covers alone (a point is covered by a map when its
// image is within `reach`, and covered alone when no other map's is): the map a missing one should
// replace is the one the others make least needed, such as the second of two maps on one part.
std::vector<std::size_t> mapsByOwnCover(std::span<const geometry::Affine3> maps, std::span<const glm::dvec3> source,
                                        std::span<const glm::dvec3> points, double reach);

struct ResidualSearch {
  const DistanceGrid* grid = nullptr;
  glm::dvec3 cloudMean{0.0};
  std::span<const glm::dvec3> cloudProbes;   // spread points of the cloud (their images must lie in it)
  std::span<const glm::dmat3> orientations;  // the starting orientations, reflections included
  // How deep the coarse vote ranks in full: it stops summing a candidate's score once the score
  // cannot rank among the voteDepth best so far, and scores the rest only when the candidates
  // kept lie deeper (never, so far). The candidates are the same at every depth; 0 scores every
  // candidate in full.
  std::size_t voteDepth = 2000;
  // The threads the coarse vote runs on (the calling one and threads - 1 more); the candidates are
  // the same on any number.
  int threads = 1;
};

// Up to `wanted` candidate maps whose image lies in the cloud and covers `residual`, best first,
// apart from each other. None when the residual has fewer than 8 points.
std::vector<geometry::Affine3> residualCandidates(const ResidualSearch& search, std::span<const glm::dvec3> residual, std::size_t wanted);

}  // namespace glass::course
