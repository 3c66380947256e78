// The fit battery (not a test): `glass ifs3d fit`'s search on clouds of random IFS that nobody
// chose by hand (glass/course/ifs3d_random.h), with the success rate as numbers. Two fixed seed
// lists: the tuning list, which the search may be improved against, and the held-out list, to be
// run only to measure the finished search. Odd seeds get 5% of their points replaced by noise.
//
//   ifs3d_fit_battery [tuning|held-out] [--points N] [--first K] [--count C]
//
// A fit succeeds when every entry of every found 3 x 4 matrix is within kTolerance of the true
// one (maps paired in the best order).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "glass/course/ifs3d_fit.h"
#include "glass/course/ifs3d_random.h"

namespace {

constexpr double kTolerance = 0.03;

std::uint64_t seedOf(bool heldOut, int index) { return (heldOut ? 1001u : 1u) + static_cast<std::uint64_t>(index); }

}  // namespace

int main(int argc, char** argv) {
  bool heldOut = false;
  std::size_t points = 10000;
  int first = 0, count = 16;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "tuning") {
      heldOut = false;
    } else if (arg == "held-out") {
      heldOut = true;
    } else if (arg == "--points" && i + 1 < argc) {
      points = static_cast<std::size_t>(std::atol(argv[++i]));
    } else if (arg == "--first" && i + 1 < argc) {
      first = std::atoi(argv[++i]);
    } else if (arg == "--count" && i + 1 < argc) {
      count = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: ifs3d_fit_battery [tuning|held-out] [--points N] [--first K] [--count C]\n");
      return 2;
    }
  }
  std::printf("%s seeds, %zu points a cloud, success: every matrix entry within %.2f\n", heldOut ? "held-out" : "tuning", points,
              kTolerance);
  std::printf("%6s %6s %8s %10s %10s %10s %10s %9s %8s\n", "seed", "noise", "sum|det|", "map error", "collage", "regen.", "spacing", "converged",
              "seconds");
  int successes = 0, converged = 0, wrongButConverged = 0;
  double totalSeconds = 0.0;
  for (int index = first; index < first + count; ++index) {
    const std::uint64_t seed = seedOf(heldOut, index);
    const glass::geometry::IteratedFunctionSystem3 ifs = glass::course::randomIfs3(seed);
    const double noise = seed % 2 == 1 ? 0.05 : 0.0;
    const std::vector<glm::dvec3> cloud = glass::course::ifs3Cloud(ifs, points, noise, seed + 5);
    const auto start = std::chrono::steady_clock::now();
    const glass::course::Ifs3Fit fit = glass::course::fitIfs3(cloud);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<glass::geometry::Affine3> truth;
    for (const auto& map : ifs.maps) truth.push_back(map.transform);
    const double error = glass::course::ifs3MapError(truth, fit.maps);
    const bool success = error < kTolerance;
    successes += success;
    converged += fit.converged();
    wrongButConverged += !success && fit.converged();
    totalSeconds += seconds;
    // The Chamfer distance between the cloud and a cloud regenerated from the found maps, as
    // `glass ifs3d fit` prints it.
    glass::geometry::IteratedFunctionSystem3 found;
    for (const auto& map : fit.maps) found.maps.push_back({map, std::nullopt, std::nullopt});
    const double regenerated = glass::course::chamferDistance(cloud, glass::course::ifs3Cloud(found, points, 0.0, seed + 11));
    double volume = 0.0;  // the share of volume the maps keep: near 1 or above, a solid attractor
    for (const auto& map : ifs.maps) volume += std::abs(map.transform.determinant());
    std::printf("%6llu %6.2f %8.3f %10.4f %10.6f %10.6f %10.6f %9s %8.2f%s\n", static_cast<unsigned long long>(seed), noise, volume, error,
                fit.trimmedCollageDistance, regenerated, fit.pointSpacing, fit.converged() ? "yes" : "no", seconds, success ? "" : "  WRONG");
    std::fflush(stdout);
  }
  std::printf("found the maps: %d of %d (%.0f%%); said converged: %d; wrong but said converged: %d; mean %.2f s a fit\n",
              successes, count, 100.0 * successes / count, converged, wrongButConverged, totalSeconds / count);
  return 0;
}
