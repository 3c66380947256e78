// Finding the maps of a 3D IFS from a cloud of points of its attractor (homework 3), by the
// collage theorem (Barnsley, "Fractals Everywhere", section III.10): if the union of the images
// f_1(P) u ... u f_k(P) of the cloud P is close to P, the attractor of the f_i is close to P.
// The fit minimises that "collage distance" (a symmetric Chamfer distance, below):
//  1. A start: the cloud split into k parts by k-means (each part should be one f_i(P)); each
//     part fitted by an affine map of the whole cloud onto it, from many starting orientations
//     (rotations of the octahedral group and offsets of them, with and without a reflection),
//     each orientation refined a few steps, the best kept.
//  2. Joint refinement: all k maps together, by alternating nearest-neighbour correspondences
//     between P and the union of the images (through k-d trees, both ways, so that no map can
//     shrink onto a corner) with affine least squares per map. The worst 10% of the
//     correspondences each way are left out (trimmed), so that noise points pull no map.
//  3. Several starts (k-means seeds), and each map re-seeded from the part of the cloud the
//     others leave uncovered; the smallest collage distance wins. When it is not well below the
//     cloud's own point spacing, the whole search is repeated from other seeds (3 attempts).
// Everything is seeded: the same cloud gives the same maps.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "glass/geometry/affine3d.h"

namespace glass::course {

struct Ifs3FitOptions {
  int maps = 4;
  int sample = 2000;        // points the correspondences are computed on, per step
  int starts = 2;           // k-means seeds tried per attempt
  int attempts = 4;         // whole attempts from other seeds, while the collage distance is not
                            // well below the cloud's point spacing
  int refineSteps = 40;     // joint refinement steps, at most
  double trim = 0.10;       // share of correspondences left out each way
  std::uint64_t seed = 1;
};

struct Ifs3Fit {
  std::vector<geometry::Affine3> maps;   // sorted by the image of the cloud's centre, x then y then z
  std::vector<double> shares;            // share of the cloud each map covers (chaos-game weights)
  double collageDistance = 0.0;          // chamferDistance(P, union f_i(P)) on the whole cloud
  double trimmedCollageDistance = 0.0;   // the same without the worst 10% each way (noise)
  double pointSpacing = 0.0;             // the cloud's mean nearest-neighbour distance (estimated)
  // The search found the maps when the trimmed collage distance is well below the point spacing
  // (in tests: about 0.4 of it); above, it stopped in a local minimum.
  bool converged() const { return trimmedCollageDistance < 0.6 * pointSpacing; }
};

// The symmetric Chamfer distance (mean nearest-neighbour distance from a to b and from b to a,
// averaged), through k-d trees.
double chamferDistance(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b);

// The affine map f minimising sum w_i |f(x_i) - y_i|^2 (normal equations, solved by Gaussian
// elimination with partial pivoting; a tiny ridge keeps a flat x-set solvable).
geometry::Affine3 fitAffineLeastSquares(std::span<const glm::dvec3> x, std::span<const glm::dvec3> y);

// Needs at least 20 points per map.
Ifs3Fit fitIfs3(std::span<const glm::dvec3> cloud, const Ifs3FitOptions& options = {});

}  // namespace glass::course
