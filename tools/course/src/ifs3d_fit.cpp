#include "glass/course/ifs3d_fit.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "glass/course/ifs3d_collage_path.h"
#include "glass/course/ifs3d_distance_grid.h"
#include "glass/course/ifs3d_orientations.h"
#include "glass/course/ifs3d_residual_search.h"
#include "glass/geometry/deterministic_random.h"
#include "glass/geometry/ifs3d.h"
#include "glass/geometry/kd_tree.h"
#include "glass/geometry/polar_decomposition.h"
#include "glass/geometry/portable_math.h"
#include "glass/raster/thread_count.h"

namespace glass::course {

namespace g = glass::geometry;

namespace {

// m distinct points of `points` drawn at random (all of them, in order, when m >= n).
std::vector<glm::dvec3> sample(std::span<const glm::dvec3> points, std::size_t m, std::uint64_t seed) {
  if (m >= points.size()) return {points.begin(), points.end()};
  std::vector<std::uint32_t> index(points.size());
  std::iota(index.begin(), index.end(), 0u);
  g::SplitMix64 random(seed);
  for (std::size_t i = 0; i < m; ++i) std::swap(index[i], index[i + random.below(points.size() - i)]);
  std::vector<glm::dvec3> out(m);
  for (std::size_t i = 0; i < m; ++i) out[i] = points[index[i]];
  return out;
}

// Mean of the values at or below the quantile 1 - trim, and that threshold.
struct Trimmed {
  double threshold = 0.0;
  double mean = 0.0;
};
Trimmed trimmedMean(std::vector<double> values, double trim) {
  Trimmed out;
  if (values.empty()) return out;
  const std::size_t keep = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(values.size() * (1.0 - trim))));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(keep - 1), values.end());
  out.threshold = values[keep - 1];
  double sum = 0.0;
  for (std::size_t i = 0; i < keep; ++i) sum += values[i];
  out.mean = sum / static_cast<double>(keep);
  return out;
}

// When the attempts on threads may run, shared by the threads. The first attempt runs alone for
// its first kFirstAttemptAlone queries: many clouds are fitted by then (the homework cloud at
// 50,000 points in 2.7 million; on the fit battery's 10,000-point clouds those found on the first
// attempt took 2.0 to 8.3 million), and attempts begun beside it would slow it down (on a loaded
// machine, or where threads share caches) only to be cancelled. Once the attempts finished
// decide the fit (chooseAttempt), the later ones are not needed.
class AttemptSchedule {
 public:
  static constexpr std::uint64_t kFirstAttemptAlone = 4'000'000;
  explicit AttemptSchedule(int attempts) : needed_(attempts) {}

  void firstAttemptWorked(std::uint64_t used) {
    if (used >= kFirstAttemptAlone) letOthersStart();
  }
  void letOthersStart() {
    const std::lock_guard<std::mutex> lock(mutex_);
    othersMayStart_ = true;
    othersMayStartChanged_.notify_all();
  }
  void waitUntilOthersMayStart() {
    std::unique_lock<std::mutex> lock(mutex_);
    othersMayStartChanged_.wait(lock, [&] { return othersMayStart_; });
  }

  void needOnly(int attempts) {
    int needed = needed_.load();
    while (attempts < needed && !needed_.compare_exchange_weak(needed, attempts)) {
    }
  }
  bool cancelled(int attempt) const { return attempt >= needed_.load(std::memory_order_relaxed); }

 private:
  std::atomic<int> needed_;
  std::mutex mutex_;
  std::condition_variable othersMayStartChanged_;
  bool othersMayStart_ = false;
};

// Thrown out of an attempt that is no longer needed, at its next batch of queries.
struct AttemptCancelled {};

// The search's work, counted as it goes in nearest-neighbour queries (k-d tree searches, most of
// its time), against the budget of Ifs3FitOptions::workBudget. Counted rather than timed, so that
// where the search stops depends on the cloud alone, not on the machine or its load.
struct WorkMeter {
  std::uint64_t used = 0;
  std::uint64_t budget = 0;  // 0: no limit
  // For an attempt on threads (attemptsOnThreads): its number, and where it learns that it is
  // not needed any more (it then stops at the next batch of queries: AttemptCancelled) and, for
  // the first, where it tells how far it has come.
  AttemptSchedule* schedule = nullptr;
  int attempt = 0;
  void add(std::size_t queries) {
    stopWhenCancelled();
    used += queries;
    if (schedule != nullptr && attempt == 0) schedule->firstAttemptWorked(used);
  }
  // Also called in the few long stretches without queries.
  void stopWhenCancelled() const {
    if (schedule != nullptr && schedule->cancelled(attempt)) throw AttemptCancelled{};
  }
  bool spent() const { return budget != 0 && used >= budget; }
};

struct Moments {
  glm::dvec3 mean{0.0};
  glm::dmat3 covariance{0.0};
};
Moments moments(std::span<const glm::dvec3> points) {
  Moments m;
  for (const glm::dvec3& p : points) m.mean += p;
  m.mean /= static_cast<double>(points.size());
  for (const glm::dvec3& p : points) {
    const glm::dvec3 d = p - m.mean;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) m.covariance[c][r] += d[r] * d[c];
  }
  m.covariance /= static_cast<double>(points.size());
  return m;
}

// Sigma^power for a symmetric positive semi-definite Sigma (power 1/2 or -1/2); eigenvalues are
// floored so that a flat part still gives a finite matrix.
glm::dmat3 symmetricPower(const glm::dmat3& sigma, double power) {
  const g::SymmetricEigen e = g::symmetricEigen(sigma);
  const double floor = std::max(e.values[0], 1e-300) * 1e-8;
  glm::dmat3 d(0.0);
  for (int k = 0; k < 3; ++k) d[k][k] = portable::pow(std::max(e.values[k], floor), power);
  return e.vectors * d * glm::transpose(e.vectors);
}

// Symmetric trimmed ICP for affine maps: moves the maps f_i so that the union of f_i(source)
// matches `target` (whose k-d tree is given), measured on `targetSample`. The least squares use
// the correspondences left after trimming, and so does the score, the trimmed symmetric Chamfer
// distance. Returns the best score seen with `maps` set to the maps that scored it.
double refine(std::vector<g::Affine3>& maps, std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
              const g::KdTree3& targetTree, std::span<const glm::dvec3> targetSample, int steps, double trim, WorkMeter& work) {
  const std::size_t k = maps.size(), n = source.size();
  double bestScore = std::numeric_limits<double>::infinity();
  std::vector<g::Affine3> bestMaps = maps;
  std::vector<glm::dvec3> images(k * n);
  std::vector<double> forward(k * n), backward(targetSample.size());
  std::vector<std::uint32_t> forwardMatch(k * n), backwardMatch(targetSample.size());
  int stalled = 0;
  for (int step = 0; step <= steps; ++step) {
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t s = 0; s < n; ++s) images[i * n + s] = maps[i].apply(source[s]);
    const g::KdTree3 imageTree(images);
    work.add(images.size() + targetSample.size());
    for (std::size_t j = 0; j < images.size(); ++j) {
      const g::KdTree3::Nearest nearest = targetTree.nearest(images[j]);
      forward[j] = std::sqrt(nearest.distanceSquared);
      forwardMatch[j] = nearest.index;
    }
    for (std::size_t j = 0; j < targetSample.size(); ++j) {
      const g::KdTree3::Nearest nearest = imageTree.nearest(targetSample[j]);
      backward[j] = std::sqrt(nearest.distanceSquared);
      backwardMatch[j] = nearest.index;
    }
    const Trimmed f = trimmedMean(forward, trim), b = trimmedMean(backward, trim);
    const double score = (f.mean + b.mean) / 2.0;
    if (score < bestScore) {
      stalled = score < bestScore * (1.0 - 1e-4) ? 0 : stalled + 1;
      bestScore = score;
      bestMaps = maps;
    } else {
      ++stalled;
    }
    if (step == steps || stalled >= 3) break;
    // Pairs f_i(x) ~ y, both ways, within the trimming thresholds.
    std::vector<std::vector<glm::dvec3>> xs(k), ys(k);
    for (std::size_t j = 0; j < images.size(); ++j) {
      if (forward[j] > f.threshold) continue;
      xs[j / n].push_back(source[j % n]);
      ys[j / n].push_back(target[forwardMatch[j]]);
    }
    for (std::size_t j = 0; j < targetSample.size(); ++j) {
      if (backward[j] > b.threshold) continue;
      xs[backwardMatch[j] / n].push_back(source[backwardMatch[j] % n]);
      ys[backwardMatch[j] / n].push_back(targetSample[j]);
    }
    for (std::size_t i = 0; i < k; ++i) {
      if (xs[i].size() >= 8) maps[i] = fitAffineLeastSquares(xs[i], ys[i]);
    }
  }
  maps = bestMaps;
  return bestScore;
}

// Every point of `points` under every map, map by map: image i * points.size() + s is maps[i]
// applied to points[s], so a nearest image's index divided by points.size() names its map.
std::vector<glm::dvec3> mapImages(std::span<const g::Affine3> maps, std::span<const glm::dvec3> points) {
  std::vector<glm::dvec3> images;
  images.reserve(maps.size() * points.size());
  for (const g::Affine3& map : maps)
    for (const glm::dvec3& p : points) images.push_back(map.apply(p));
  return images;
}

// The points of `sample` whose nearest image is map `part`'s (imageTree holds mapImages of the
// maps over `sourceSize` points): the part of the cloud that map accounts for.
std::vector<glm::dvec3> ownPart(const g::KdTree3& imageTree, std::size_t sourceSize, std::span<const glm::dvec3> sample,
                                std::size_t part) {
  std::vector<glm::dvec3> own;
  for (const glm::dvec3& p : sample)
    if (imageTree.nearest(p).index / sourceSize == part) own.push_back(p);
  return own;
}

// How far the attractor of `maps` is from the cloud: the trimmed symmetric Chamfer distance
// between `target` (a sample of the cloud) and as many chaos-game points of the maps (weights
// |det L_i|). The collage distance judges a map set by one step of the Hutchinson operator; this
// judges its attractor, and so catches what one step hides: two maps on the same part with a small
// part left out (within the trimming), or a map that is not contractive. Infinity when the
// points leave every bound.
double regeneratedDistance(const std::vector<g::Affine3>& maps, const g::KdTree3& targetTree, std::span<const glm::dvec3> target,
                           double trim, std::uint64_t seed, WorkMeter& work) {
  g::IteratedFunctionSystem3 ifs;
  for (const g::Affine3& map : maps) ifs.maps.push_back({map, std::nullopt, std::nullopt});
  const auto probabilities = g::chaosGameProbabilities3(ifs);
  if (!probabilities) return std::numeric_limits<double>::infinity();
  std::vector<glm::dvec3> points;
  points.reserve(target.size());
  for (const g::IfsPoint3& p : g::chaosGamePoints3(ifs, *probabilities, target.size(), seed)) {
    if (!(std::abs(p.position.x) + std::abs(p.position.y) + std::abs(p.position.z) < 1e6)) return std::numeric_limits<double>::infinity();
    points.push_back(p.position);
  }
  const g::KdTree3 pointTree(points);
  work.add(points.size() + target.size());
  std::vector<double> forward, backward;
  forward.reserve(points.size());
  backward.reserve(target.size());
  for (const glm::dvec3& p : points) forward.push_back(std::sqrt(targetTree.nearest(p).distanceSquared));
  for (const glm::dvec3& p : target) backward.push_back(std::sqrt(pointTree.nearest(p).distanceSquared));
  return (trimmedMean(forward, trim).mean + trimmedMean(backward, trim).mean) / 2.0;
}

// k-means++ seeding (Arthur and Vassilvitskii, 2007) and Lloyd's iterations; the labels.
std::vector<int> kMeans(std::span<const glm::dvec3> points, int k, std::uint64_t seed) {
  g::SplitMix64 random(seed);
  std::vector<glm::dvec3> centres{points[random.below(points.size())]};
  std::vector<double> d2(points.size());
  while (static_cast<int>(centres.size()) < k) {
    double total = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (const glm::dvec3& c : centres) best = std::min(best, glm::dot(points[i] - c, points[i] - c));
      d2[i] = best;
      total += best;
    }
    double u = random.uniform() * total;
    std::size_t chosen = points.size() - 1;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if ((u -= d2[i]) <= 0.0) {
        chosen = i;
        break;
      }
    }
    centres.push_back(points[chosen]);
  }
  std::vector<int> labels(points.size(), 0);
  for (int iteration = 0; iteration < 50; ++iteration) {
    bool changed = false;
    for (std::size_t i = 0; i < points.size(); ++i) {
      int best = 0;
      for (int c = 1; c < k; ++c) {
        if (glm::dot(points[i] - centres[static_cast<std::size_t>(c)], points[i] - centres[static_cast<std::size_t>(c)]) <
            glm::dot(points[i] - centres[static_cast<std::size_t>(best)], points[i] - centres[static_cast<std::size_t>(best)])) {
          best = c;
        }
      }
      changed = changed || labels[i] != best;
      labels[i] = best;
    }
    if (!changed && iteration > 0) break;
    std::vector<glm::dvec3> sums(static_cast<std::size_t>(k), glm::dvec3(0.0));
    std::vector<int> counts(static_cast<std::size_t>(k), 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      sums[static_cast<std::size_t>(labels[i])] += points[i];
      ++counts[static_cast<std::size_t>(labels[i])];
    }
    for (int c = 0; c < k; ++c) {
      if (counts[static_cast<std::size_t>(c)] > 0) centres[static_cast<std::size_t>(c)] = sums[static_cast<std::size_t>(c)] / static_cast<double>(counts[static_cast<std::size_t>(c)]);
    }
  }
  return labels;
}

// The affine map of the whole cloud onto one part: moments give the scale and position, the
// orientation is searched.
g::Affine3 fitPart(std::span<const glm::dvec3> cloud, const Moments& cloudMoments, std::span<const glm::dvec3> part,
                   const std::vector<glm::dmat3>& orientations, double trim, std::uint64_t seed, WorkMeter& work) {
  const Moments partMoments = moments(part);
  const glm::dmat3 partRoot = symmetricPower(partMoments.covariance, 0.5);
  const glm::dmat3 cloudInverseRoot = symmetricPower(cloudMoments.covariance, -0.5);
  const g::KdTree3 partTree(part);
  const std::vector<glm::dvec3> coarseSource = sample(cloud, 150, seed);
  const std::vector<glm::dvec3> coarseTarget = sample(part, 150, seed + 1);
  struct Candidate {
    double score;
    g::Affine3 map;
  };
  std::vector<Candidate> candidates;
  for (const glm::dmat3& q : orientations) {
    const glm::dmat3 a = partRoot * q * cloudInverseRoot;
    std::vector<g::Affine3> maps{g::Affine3::fromParts(a, partMoments.mean - a * cloudMoments.mean)};
    const double score = refine(maps, coarseSource, part, partTree, coarseTarget, 2, trim, work);
    candidates.push_back({score, maps[0]});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  const std::vector<glm::dvec3> fineSource = sample(cloud, 600, seed + 2);
  const std::vector<glm::dvec3> fineTarget = sample(part, 600, seed + 3);
  Candidate best{std::numeric_limits<double>::infinity(), candidates.front().map};
  for (std::size_t c = 0; c < std::min<std::size_t>(4, candidates.size()); ++c) {
    std::vector<g::Affine3> maps{candidates[c].map};
    const double score = refine(maps, fineSource, part, partTree, fineTarget, 15, trim, work);
    if (score < best.score) best = {score, maps[0]};
  }
  return best.map;
}

// Candidate maps found without splitting the cloud, from the property every true map has
// whatever the overlaps: f_i(P) lies in P (the collage's one direction), while a map turned,
// placed or scaled wrongly sends part of a sparse cloud off it. Candidate similarities
// x -> c + r Q (x - mean) (r from 0.3 to 0.58, the 144 starting orientations, c on a grid of
// centres in the cloud's box) are scored by how far the images of a dozen spread points fall
// from the cloud (the distance grid), the best kept per ratio; each is refined alone, against
// the cloud for its images and against the points it covers for the way back. A generalized
// Hough transform over the maps, with the collage's inclusion as the vote.
struct PoolMap {
  g::Affine3 map;
  double inclusion = 0.0;               // trimmed mean distance of its images to the cloud
  std::vector<std::uint32_t> covered;   // the points of coverSample within reach of its images
};
struct InclusionPool {
  std::vector<glm::dvec3> source, coverSample;
  double reach = 0.0;
  std::vector<PoolMap> maps;
  std::vector<std::size_t> eligible;  // the maps whose image lies in the cloud, most covering first
  // The points of coverSample within reach of the images of `maps` (of source).
  std::vector<char> coveredBy(std::span<const g::Affine3> maps, WorkMeter& work) const {
    std::vector<char> covered(coverSample.size(), 0);
    if (maps.empty()) return covered;
    const g::KdTree3 imageTree(mapImages(maps, source));
    work.add(coverSample.size());
    for (std::size_t i = 0; i < coverSample.size(); ++i) covered[i] = imageTree.nearest(coverSample[i]).distanceSquared < reach * reach;
    return covered;
  }
  // The eligible map covering most of what `covered` leaves, and how many points that is.
  std::size_t bestAddition(const std::vector<char>& covered, std::span<const std::size_t> exclude, std::size_t& gain) const {
    std::size_t best = maps.size();
    gain = 0;
    for (const std::size_t e : eligible) {
      if (std::find(exclude.begin(), exclude.end(), e) != exclude.end()) continue;
      std::size_t g = 0;
      for (const std::uint32_t i : maps[e].covered) g += !covered[i];
      if (best == maps.size() || g > gain) {
        best = e;
        gain = g;
      }
    }
    return best;
  }
};

InclusionPool inclusionPool(std::span<const glm::dvec3> cloud, const g::KdTree3& cloudTree, const Moments& cloudMoments,
                            const std::vector<glm::dmat3>& orientations, int k, double spacing, double trim, std::uint64_t seed,
                            WorkMeter& work) {
  constexpr int kResolution = 40;
  constexpr std::size_t kProbes = 12, kPerRatio = 50;
  constexpr double kRatios[] = {0.3, 0.38, 0.47, 0.58};
  const DistanceGrid grid(cloud, cloudTree, kResolution);
  work.add(static_cast<std::size_t>(grid.size(0)) * grid.size(1) * grid.size(2));
  const double h = grid.cell(), cap = 3.0 * h;
  const std::vector<glm::dvec3> spread = sample(cloud, 2000, seed);
  const std::vector<glm::dvec3> probes = spreadPoints(spread, kProbes);
  const std::vector<glm::dvec3> fineProbes = spreadPoints(spread, 4 * kProbes);
  // How far the images of the fine probes fall from the cloud, each capped: the vote the
  // candidates are climbed on.
  const GridScore inclusionScore = [&](const glm::dmat3& linear, const glm::dvec3& centre) {
    double sum = 0.0;
    for (const glm::dvec3& p : fineProbes) sum += std::min(grid.at(centre + linear * (p - cloudMoments.mean)), cap);
    return sum;
  };
  struct Candidate {
    double score;
    glm::dvec3 centre;
    std::size_t orientation;
  };
  std::vector<g::Affine3> hypotheses;
  for (const double ratio : kRatios) {
    // The probes' offsets from the mean under each orientation, scaled.
    std::vector<glm::dvec3> offsets(orientations.size() * probes.size());
    for (std::size_t q = 0; q < orientations.size(); ++q)
      for (std::size_t j = 0; j < probes.size(); ++j) offsets[q * probes.size() + j] = ratio * (orientations[q] * (probes[j] - cloudMoments.mean));
    std::vector<Candidate> candidates;
    for (int z = 0; z < grid.size(2); z += 2) {
      work.stopWhenCancelled();
      for (int y = 0; y < grid.size(1); y += 2)
        for (int x = 0; x < grid.size(0); x += 2) {
          const glm::dvec3 centre = grid.lo() + (glm::dvec3(x, y, z) + 0.5) * h;
          if (!(grid.at(centre) <= 4.0 * h)) continue;
          Candidate best{std::numeric_limits<double>::infinity(), centre, 0};
          for (std::size_t q = 0; q < orientations.size(); ++q) {
            double score = 0.0;
            for (std::size_t j = 0; j < probes.size() && score < best.score; ++j)
              score += std::min(grid.at(centre + offsets[q * probes.size() + j]), cap);
            if (score < best.score) best = {score, centre, q};
          }
          candidates.push_back(best);
        }
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
    std::vector<Candidate> kept;
    for (const Candidate& c : candidates) {
      if (kept.size() == kPerRatio) break;
      // Apart from those kept, in centre or in orientation: the best-scoring candidates
      // otherwise crowd into the densest spot (overlapping parts share a spot, but not their
      // orientation).
      const bool near = std::any_of(kept.begin(), kept.end(), [&](const Candidate& other) {
        if (glm::length(other.centre - c.centre) >= 2.5 * h) return false;
        const glm::dmat3 d = orientations[other.orientation] - orientations[c.orientation];
        double largest = 0.0;
        for (int col = 0; col < 3; ++col)
          for (int row = 0; row < 3; ++row) largest = std::max(largest, std::abs(d[col][row]));
        return largest < 0.5;
      });
      if (!near) kept.push_back(c);
    }
    for (Candidate c : kept) {
      work.stopWhenCancelled();
      const glm::dmat3 a = climbOnGrid(inclusionScore, ratio * orientations[c.orientation], c.centre, h);
      hypotheses.push_back(g::Affine3::fromParts(a, c.centre - a * cloudMoments.mean));
    }
  }

  // Each refined alone: its images against the whole cloud, the way back from the cloud points
  // it covers, which are found again between rounds as the map moves.
  InclusionPool pool;
  pool.source = sample(cloud, 150, seed + 1);
  pool.coverSample = sample(cloud, 2000, seed + 2);
  pool.reach = 1.5 * h;
  const std::vector<glm::dvec3> inclusionSource = sample(cloud, 300, seed + 3);
  const auto coveredIndices = [&](const g::Affine3& map) {
    const std::vector<char> covered = pool.coveredBy(std::span<const g::Affine3>(&map, 1), work);
    std::vector<std::uint32_t> indices;
    for (std::size_t i = 0; i < covered.size(); ++i)
      if (covered[i]) indices.push_back(static_cast<std::uint32_t>(i));
    return indices;
  };
  for (g::Affine3 map : hypotheses) {
    for (int round = 0; round < 2; ++round) {
      const std::vector<std::uint32_t> covered = coveredIndices(map);
      if (covered.size() < 10) break;
      std::vector<glm::dvec3> part;
      for (const std::uint32_t i : covered) part.push_back(pool.coverSample[i]);
      std::vector<g::Affine3> maps{map};
      refine(maps, pool.source, cloud, cloudTree, part, 4, trim, work);
      map = maps[0];
    }
    // A map that is not contractive cannot be one of the system's.
    if (!(std::abs(map.determinant()) < 0.9)) continue;
    std::vector<double> forward;
    for (const glm::dvec3& p : inclusionSource) forward.push_back(std::sqrt(cloudTree.nearest(map.apply(p)).distanceSquared));
    pool.maps.push_back({map, trimmedMean(forward, trim).mean, coveredIndices(map)});
  }
  // The maps whose image lies in the cloud: within a few point spacings of it (2.4: see
  // Ifs3Fit::converged); at least 4k of the best when fewer do.
  for (std::size_t i = 0; i < pool.maps.size(); ++i)
    if (pool.maps[i].inclusion < 2.4 * spacing) pool.eligible.push_back(i);
  if (pool.eligible.size() < static_cast<std::size_t>(k)) {
    pool.eligible.resize(pool.maps.size());
    std::iota(pool.eligible.begin(), pool.eligible.end(), std::size_t{0});
    std::stable_sort(pool.eligible.begin(), pool.eligible.end(),
                     [&](std::size_t a, std::size_t b) { return pool.maps[a].inclusion < pool.maps[b].inclusion; });
    pool.eligible.resize(std::min<std::size_t>(pool.eligible.size(), 4 * static_cast<std::size_t>(k)));
  }
  std::stable_sort(pool.eligible.begin(), pool.eligible.end(),
                   [&](std::size_t a, std::size_t b) { return pool.maps[a].covered.size() > pool.maps[b].covered.size(); });
  return pool;
}

// Sets of k maps chosen greedily from the pool to cover the cloud, each set starting from
// another of the most covering maps.
std::vector<std::vector<g::Affine3>> greedyStarts(const InclusionPool& pool, int k, int wanted) {
  std::vector<std::vector<g::Affine3>> starts;
  for (std::size_t first = 0; first < pool.eligible.size() && static_cast<int>(starts.size()) < wanted; ++first) {
    std::vector<std::size_t> chosen{pool.eligible[first]};
    std::vector<char> covered(pool.coverSample.size(), 0);
    for (const std::uint32_t i : pool.maps[chosen[0]].covered) covered[i] = 1;
    while (chosen.size() < static_cast<std::size_t>(k)) {
      std::size_t gain = 0;
      const std::size_t next = pool.bestAddition(covered, chosen, gain);
      if (next == pool.maps.size()) break;
      chosen.push_back(next);
      for (const std::uint32_t i : pool.maps[next].covered) covered[i] = 1;
    }
    if (chosen.size() < static_cast<std::size_t>(k)) break;
    std::vector<g::Affine3> maps;
    for (const std::size_t c : chosen) maps.push_back(pool.maps[c].map);
    starts.push_back(maps);
  }
  return starts;
}

}  // namespace

double chamferDistance(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  const g::KdTree3 treeA(a), treeB(b);
  double ab = 0.0, ba = 0.0;
  for (const glm::dvec3& p : a) ab += std::sqrt(treeB.nearest(p).distanceSquared);
  for (const glm::dvec3& p : b) ba += std::sqrt(treeA.nearest(p).distanceSquared);
  return (ab / static_cast<double>(a.size()) + ba / static_cast<double>(b.size())) / 2.0;
}

g::Affine3 fitAffineLeastSquares(std::span<const glm::dvec3> x, std::span<const glm::dvec3> y) {
  // Normal equations for the rows of [A | t]: (sum h h^T) r_j = sum h y_j, h = (x, 1). The points
  // are centred first, which keeps the system well conditioned.
  glm::dvec3 cx(0.0), cy(0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    cx += x[i];
    cy += y[i];
  }
  cx /= static_cast<double>(x.size());
  cy /= static_cast<double>(y.size());
  double m[3][3] = {}, rhs[3][3] = {};  // rhs[j]: for output coordinate j
  for (std::size_t i = 0; i < x.size(); ++i) {
    const glm::dvec3 dx = x[i] - cx, dy = y[i] - cy;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] += dx[r] * dx[c];
      for (int j = 0; j < 3; ++j) rhs[j][r] += dx[r] * dy[j];
    }
  }
  const double ridge = 1e-12 * (m[0][0] + m[1][1] + m[2][2]) + 1e-300;
  for (int r = 0; r < 3; ++r) m[r][r] += ridge;
  // Gaussian elimination with partial pivoting, the three right-hand sides at once.
  int order[3] = {0, 1, 2};
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 3; ++r)
      if (std::abs(m[order[r]][col]) > std::abs(m[order[pivot]][col])) pivot = r;
    std::swap(order[col], order[pivot]);
    const int p = order[col];
    for (int r = col + 1; r < 3; ++r) {
      const int row = order[r];
      const double factor = m[row][col] / m[p][col];
      for (int c = col; c < 3; ++c) m[row][c] -= factor * m[p][c];
      for (int j = 0; j < 3; ++j) rhs[j][row] -= factor * rhs[j][p];
    }
  }
  glm::dmat3 a(0.0);
  for (int j = 0; j < 3; ++j) {
    double solution[3];
    for (int col = 2; col >= 0; --col) {
      const int row = order[col];
      double v = rhs[j][row];
      for (int c = col + 1; c < 3; ++c) v -= m[row][c] * solution[c];
      solution[col] = v / m[row][col];
    }
    for (int c = 0; c < 3; ++c) a[c][j] = solution[c];  // row j of A
  }
  return g::Affine3::fromParts(a, cy - a * cx);
}

namespace {

// Sets of maps taken from the inclusion search, each refined and ranked.
constexpr int kInclusionStarts = 4;
// The residual search (ifs3d_residual_search.h): points uncovered when farther from every image
// of the cloud than this many point spacings, at most this many of them, joined into clusters
// within this many grid cells; the largest clusters searched while they hold at least this share
// of the points; candidates from each, each tried in place of this many of the least needed maps,
// refined this many steps before the best of all is refined in full.
constexpr double kUncoveredSpacings = 2.4;  // tuned as 3 times 0.8 of the spacing (Ifs3Fit::converged)
constexpr std::size_t kResidualMostPoints = 3000;
constexpr double kResidualLink = 1.5;
constexpr std::size_t kResidualClusters = 2;
constexpr double kResidualMinimumShare = 0.004;
constexpr std::size_t kResidualCandidates = 3, kResidualTargets = 2;
constexpr int kResidualTrialSteps = 8;
constexpr int kResidualGridResolution = 40;

// The maps measured on the whole cloud (Ifs3Fit), sorted by where they send its centre.
Ifs3Fit measuredFit(std::vector<g::Affine3> winner, std::span<const glm::dvec3> cloud, const g::KdTree3& cloudTree,
                    const Ifs3FitOptions& options, double spacing, WorkMeter& work) {
  Ifs3Fit best;
  const glm::dvec3 centre = moments(cloud).mean;
  std::stable_sort(winner.begin(), winner.end(), [&](const g::Affine3& a, const g::Affine3& b) {
    const glm::dvec3 pa = a.apply(centre), pb = b.apply(centre);
    if (pa.x != pb.x) return pa.x < pb.x;
    if (pa.y != pb.y) return pa.y < pb.y;
    return pa.z < pb.z;
  });
  best.maps = winner;
  best.pointSpacing = spacing;
  // The collage distance on the whole cloud, plain and with the worst few per cent each way left
  // out (rankTrim) as the search ranks candidates (the cloud has no isolated noise points left,
  // withoutIsolatedPoints), and the shares: which map's image is nearest to each cloud point.
  const std::vector<glm::dvec3> images = mapImages(winner, cloud);
  const g::KdTree3 imageTree(images);
  work.add(images.size() + cloud.size());
  std::vector<double> forward, backward;
  forward.reserve(images.size());
  backward.reserve(cloud.size());
  std::vector<double> counts(winner.size(), 0.0);
  for (const glm::dvec3& p : images) forward.push_back(std::sqrt(cloudTree.nearest(p).distanceSquared));
  for (const glm::dvec3& p : cloud) {
    const g::KdTree3::Nearest nearest = imageTree.nearest(p);
    backward.push_back(std::sqrt(nearest.distanceSquared));
    counts[nearest.index / cloud.size()] += 1.0;
  }
  const auto mean = [](const std::vector<double>& values) {
    double sum = 0.0;
    for (const double v : values) sum += v;
    return sum / static_cast<double>(values.size());
  };
  best.collageDistance = (mean(backward) + mean(forward)) / 2.0;
  best.trimmedCollageDistance = (trimmedMean(forward, options.rankTrim).mean + trimmedMean(backward, options.rankTrim).mean) / 2.0;
  best.regeneratedDistance = regeneratedDistance(winner, cloudTree, cloud, options.rankTrim, options.seed + 43, work);
  for (double& c : counts) c /= static_cast<double>(cloud.size());
  best.shares = counts;
  return best;
}

// The maps a search stage leaves, finished: a last refinement on a larger sample, then measured.
Ifs3Fit finishedFit(std::vector<g::Affine3> winner, std::span<const glm::dvec3> cloud, const g::KdTree3& cloudTree,
                    const Ifs3FitOptions& options, double spacing, WorkMeter& work) {
  const std::size_t perStep = static_cast<std::size_t>(std::max(options.sample, 50));
  const std::vector<glm::dvec3> largeSource = sample(cloud, 2 * perStep, options.seed + 21);
  const std::vector<glm::dvec3> largeTarget = sample(cloud, 4 * perStep, options.seed + 22);
  refine(winner, largeSource, cloud, cloudTree, largeTarget, options.refineSteps, options.trim, work);
  return measuredFit(std::move(winner), cloud, cloudTree, options, spacing, work);
}

// One attempt of the whole fit, from the seed in options: from k-means splits of the cloud, or
// from the inclusion search.
Ifs3Fit fitOnce(std::span<const glm::dvec3> cloud, const g::KdTree3& cloudTree, const Ifs3FitOptions& options, double spacing,
                bool withPool, bool fromPool, WorkMeter& work) {
  const int k = std::max(1, options.maps);
  const Moments cloudMoments = moments(cloud);
  const std::vector<glm::dmat3> orientations = startingOrientations();
  const std::size_t perStep = static_cast<std::size_t>(std::max(options.sample, 50));
  const std::vector<glm::dvec3> clusterSample = sample(cloud, 4 * perStep, options.seed);
  const std::vector<glm::dvec3> source = sample(cloud, perStep / 2 + 1, options.seed + 11);
  const std::vector<glm::dvec3> targetSample = sample(cloud, perStep, options.seed + 12);

  // Candidates are compared by the distance of their attractor to the cloud (regenerated by the
  // chaos game, always from the same seed, so that two candidates see the same random choices).
  const g::KdTree3 targetSampleTree(targetSample);
  // A candidate whose chaos game runs off (a map not yet contractive) ranks after every one that
  // has an attractor, by its collage distance.
  const auto attractorDistance = [&](const std::vector<g::Affine3>& maps, double collage) {
    const double d = regeneratedDistance(maps, targetSampleTree, targetSample, options.rankTrim, options.seed + 41, work);
    return std::isfinite(d) ? d : 1e6 + collage;
  };
  // The collage distance trimmed only as the ranking is (rankTrim): the refinement's own trims
  // more, and a map partly off the cloud can hide in that share.
  const auto strictCollage = [&](std::vector<g::Affine3> maps) {
    return refine(maps, source, cloud, cloudTree, targetSample, 0, options.rankTrim, work);
  };
  std::vector<g::Affine3> winner;
  double winnerScore = std::numeric_limits<double>::infinity();
  // Early exit: after a stage that found a closer winner, the winner is measured on the whole
  // cloud; when it has converged, it is finished and returned, since the later stages only look
  // for a closer one. Most clouds are fitted by the first stages, so this saves most of an attempt.
  std::vector<g::Affine3> checked;
  const auto convergedWinner = [&]() -> std::optional<Ifs3Fit> {
    if (winner.empty() || winner == checked) return std::nullopt;
    checked = winner;
    if (!measuredFit(winner, cloud, cloudTree, options, spacing, work).converged()) return std::nullopt;
    Ifs3Fit fit = finishedFit(winner, cloud, cloudTree, options, spacing, work);
    if (!fit.converged()) return std::nullopt;
    return fit;
  };
  InclusionPool pool;
  if (withPool) pool = inclusionPool(cloud, cloudTree, cloudMoments, orientations, k, spacing, options.trim, options.seed, work);
  if (fromPool) {
    for (std::vector<g::Affine3>& maps : greedyStarts(pool, k, kInclusionStarts)) {
      if (work.spent() && !winner.empty()) break;
      const double collage = refine(maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim, work);
      const double score = attractorDistance(maps, collage);
      if (score < winnerScore) {
        winnerScore = score;
        winner = maps;
      }
    }
  }
  for (int start = 0; start < (fromPool && !winner.empty() ? 0 : std::max(1, options.starts)); ++start) {
    if (work.spent() && !winner.empty()) break;
    const std::uint64_t seed = options.seed + 1000 * static_cast<std::uint64_t>(start + 1);
    const std::vector<int> labels = kMeans(clusterSample, k, seed);
    std::vector<g::Affine3> maps;
    for (int part = 0; part < k; ++part) {
      std::vector<glm::dvec3> points;
      for (std::size_t i = 0; i < clusterSample.size(); ++i)
        if (labels[i] == part) points.push_back(clusterSample[i]);
      if (points.size() < 10) points = sample(clusterSample, 10, seed + static_cast<std::uint64_t>(part));
      maps.push_back(fitPart(cloud, cloudMoments, points, orientations, options.trim, seed + 7 * static_cast<std::uint64_t>(part), work));
    }
    const double collage = refine(maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim, work);
    const double score = attractorDistance(maps, collage);
    if (score < winnerScore) {
      winnerScore = score;
      winner = maps;
    }
  }

  // Re-seeding, each map in turn, the others kept; the result is kept when the collage distance
  // goes down. The map's part is taken two ways: first the points the other maps' images leave
  // uncovered (farther from them than three times the typical distance to all images), which
  // finds a map's part even when the map itself is wrong; then the points whose nearest image is
  // the map's own, better when parts overlap.
  if (auto fit = convergedWinner()) return std::move(*fit);
  for (int round = 0; round < 2 * k && !work.spent(); ++round) {
    const int part = round % k;
    const bool uncovered = round < k;
    std::vector<glm::dvec3> images, others;
    for (std::size_t i = 0; i < winner.size(); ++i) {
      for (const glm::dvec3& p : source) {
        images.push_back(winner[i].apply(p));
        if (i != static_cast<std::size_t>(part)) others.push_back(images.back());
      }
    }
    const g::KdTree3 imageTree(images);
    work.add((uncovered ? 2 : 1) * clusterSample.size());
    std::vector<glm::dvec3> points;
    if (uncovered) {
      if (others.empty()) continue;
      const g::KdTree3 otherTree(others);
      std::vector<double> distances;
      for (const glm::dvec3& p : clusterSample) distances.push_back(std::sqrt(imageTree.nearest(p).distanceSquared));
      const double typical = trimmedMean(distances, 0.5).threshold;  // the median
      for (const glm::dvec3& p : clusterSample) {
        if (std::sqrt(otherTree.nearest(p).distanceSquared) > 3.0 * typical) points.push_back(p);
      }
    } else {
      points = ownPart(imageTree, source.size(), clusterSample, static_cast<std::size_t>(part));
    }
    if (points.size() < 10) continue;
    std::vector<g::Affine3> maps = winner;
    maps[static_cast<std::size_t>(part)] =
        fitPart(cloud, cloudMoments, points, orientations, options.trim, options.seed + 31 * static_cast<std::uint64_t>(round + 1), work);
    const double collage = refine(maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim, work);
    const double score = attractorDistance(maps, collage);
    if (score < winnerScore) {
      winnerScore = score;
      winner = maps;
    }
  }

  // Re-seeding from the pool: each map in turn, then each pair of maps, replaced by the maps of
  // the pool that cover most of what the others leave (greedily), when that beats the winner.
  if (auto fit = convergedWinner()) return std::move(*fit);
  std::vector<std::vector<int>> replaced;
  for (int a = 0; a < (pool.maps.empty() ? 0 : k); ++a) replaced.push_back({a});
  for (int a = 0; a < (pool.maps.empty() ? 0 : k); ++a)
    for (int b = a + 1; b < k; ++b) replaced.push_back({a, b});
  for (const std::vector<int>& parts : replaced) {
    if (work.spent()) break;
    std::vector<g::Affine3> kept;
    for (int i = 0; i < k; ++i)
      if (std::find(parts.begin(), parts.end(), i) == parts.end()) kept.push_back(winner[static_cast<std::size_t>(i)]);
    std::vector<char> covered = pool.coveredBy(kept, work);
    std::vector<std::size_t> chosen;
    for (std::size_t n = 0; n < parts.size(); ++n) {
      std::size_t gain = 0;
      const std::size_t next = pool.bestAddition(covered, chosen, gain);
      if (next == pool.maps.size() || gain == 0) break;
      chosen.push_back(next);
      for (const std::uint32_t i : pool.maps[next].covered) covered[i] = 1;
    }
    if (chosen.size() != parts.size()) continue;
    std::vector<g::Affine3> maps = winner;
    for (std::size_t n = 0; n < parts.size(); ++n) maps[static_cast<std::size_t>(parts[n])] = pool.maps[chosen[n]].map;
    const double collage = refine(maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim, work);
    const double score = attractorDistance(maps, collage);
    if (score < winnerScore) {
      winnerScore = score;
      winner = maps;
    }
  }

  // Re-seeding from the residual: the points no image reaches lie in the image of a map the
  // winner lacks (ifs3d_residual_search.h); the candidates found for them replace the maps the
  // others make least needed, when that beats the winner. Again while it helps.
  if (auto fit = convergedWinner()) return std::move(*fit);
  if (!work.spent()) {
    const DistanceGrid grid(cloud, cloudTree, kResidualGridResolution);
    work.add(static_cast<std::size_t>(grid.size(0)) * grid.size(1) * grid.size(2));
    const std::vector<glm::dvec3> cloudProbes = sample(cloud, 2000, options.seed + 51);
    ResidualSearch search{&grid, cloudMoments.mean, cloudProbes, orientations};
    search.threads = options.threads > 0 ? options.threads : raster::configuredThreadCount();
    // The best of the maps `base` becomes with candidates for its residual's largest clusters in
    // place of its least needed maps, each refined briefly, ranked by their attractor; or, on the
    // collage path (`byCollage`), in place of the maps whose image lies farthest out of the cloud,
    // the candidates of the two largest clusters also together, ranked by the collage distance.
    struct Trial {
      std::vector<g::Affine3> maps;
      double score = std::numeric_limits<double>::infinity();
    };
    const auto bestResidualTrial = [&](const std::vector<g::Affine3>& base, bool byCollage) {
      Trial best;
      std::vector<glm::dvec3> residual = uncoveredPoints(base, cloud, clusterSample, kUncoveredSpacings * spacing);
      work.add((1 + base.size()) * clusterSample.size());  // and as many for the maps' own cover
      if (residual.size() > kResidualMostPoints) residual = sample(residual, kResidualMostPoints, options.seed + 53);
      // On the path, the maps to replace are those whose image lies farthest out of the cloud
      // (a right map's lies in it whatever the others do); otherwise the least needed.
      const std::vector<std::size_t> replaceable =
          byCollage ? mapsByInclusion(base, source, cloudTree, options.rankTrim) : mapsByOwnCover(base, source, clusterSample, 1.5 * grid.cell());
      if (byCollage) work.add(base.size() * source.size());
      const auto tryMaps = [&](std::vector<g::Affine3> maps) {
        const double collage = refine(maps, source, cloud, cloudTree, targetSample, kResidualTrialSteps, options.trim, work);
        if (byCollage && !stretchesWithinCollagePath(maps)) return;
        const double score = byCollage ? strictCollage(maps) : attractorDistance(maps, collage);
        if (score < best.score) best = {std::move(maps), score};
      };
      const std::vector<std::vector<glm::dvec3>> clusters = residualClusters(residual, kResidualLink * grid.cell());
      std::vector<std::vector<g::Affine3>> candidates;  // per cluster
      for (std::size_t n = 0; n < std::min<std::size_t>(kResidualClusters, clusters.size()); ++n) {
        if (clusters[n].size() < kResidualMinimumShare * static_cast<double>(clusterSample.size())) break;
        candidates.push_back(residualCandidates(search, clusters[n], kResidualCandidates));
        for (const g::Affine3& candidate : candidates.back()) {
          for (std::size_t r = 0; r < std::min<std::size_t>(kResidualTargets, replaceable.size()) && !work.spent(); ++r) {
            std::vector<g::Affine3> maps = base;
            maps[replaceable[r]] = candidate;
            tryMaps(std::move(maps));
          }
        }
      }
      if (byCollage && candidates.size() == 2 && replaceable.size() >= 2) {
        for (const g::Affine3& first : candidates[0])
          for (const g::Affine3& second : candidates[1])
            for (int swapped = 0; swapped < 2 && !work.spent(); ++swapped) {
              std::vector<g::Affine3> maps = base;
              maps[replaceable[swapped]] = first;
              maps[replaceable[1 - swapped]] = second;
              tryMaps(std::move(maps));
            }
      }
      return best;
    };
    for (int round = 0; round < options.residualRounds && !work.spent(); ++round) {
      if (round > 0)
        if (auto fit = convergedWinner()) return std::move(*fit);
      Trial trial = bestResidualTrial(winner, false);
      if (trial.maps.empty()) break;
      const double collage = refine(trial.maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim, work);
      const double score = attractorDistance(trial.maps, collage);
      if (!(score < winnerScore)) break;
      winnerScore = score;
      winner = std::move(trial.maps);
    }
    // When no candidate brings the attractor closer, several maps are wrong at once: the residual
    // lies in many pieces, and a right map for one of them leaves the attractor as far as before
    // while the others are wrong. The collage distance sees each right map (its image lies in the
    // cloud and covers its piece), so a path of replacements, each lowering the collage distance,
    // goes on from the winner; the winner becomes its end when that attractor is closer.
    if (options.collagePathRounds > 0)
      if (auto fit = convergedWinner()) return std::move(*fit);
    std::vector<g::Affine3> path = winner;
    double pathCollage = options.collagePathRounds > 0 ? strictCollage(path) : 0.0;
    for (int round = 0; round < options.collagePathRounds && !work.spent(); ++round) {
      Trial trial = bestResidualTrial(path, true);
      if (trial.maps.empty()) break;
      refine(trial.maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim, work);
      const double collage = stretchesWithinCollagePath(trial.maps) ? strictCollage(trial.maps) : std::numeric_limits<double>::infinity();
      if (!(collage < pathCollage)) break;
      path = std::move(trial.maps);
      pathCollage = collage;
      const double score = attractorDistance(path, collage);
      if (score < winnerScore) {
        winnerScore = score;
        winner = path;
        if (auto fit = convergedWinner()) return std::move(*fit);
      }
    }

    // Each map searched afresh for its own part. Where parts overlap much, a wrong map can hide
    // inside the others: flattened onto a sheet, or turned the wrong way, its image still lies in
    // the cloud and the others cover what it misses, so it leaves no residual for the steps above
    // and refinement keeps it. Its part (the points whose nearest image is its own) must still
    // lie in the true map's image, so the votes of the residual search (f(P) in P, the part in
    // f(P)) find candidates for it, which replace it when the attractor comes closer.
    if (auto fit = convergedWinner()) return std::move(*fit);
    // The images change only when a map is replaced; the tree is rebuilt then.
    g::KdTree3 imageTree(mapImages(winner, source));
    for (std::size_t part = 0; part < winner.size() && !work.spent(); ++part) {
      work.add(clusterSample.size());
      const std::vector<glm::dvec3> own = ownPart(imageTree, source.size(), clusterSample, part);
      Trial best;
      for (const g::Affine3& candidate : residualCandidates(search, own, kResidualCandidates)) {
        std::vector<g::Affine3> maps = winner;
        maps[part] = candidate;
        const double collage = refine(maps, source, cloud, cloudTree, targetSample, kResidualTrialSteps, options.trim, work);
        const double score = attractorDistance(maps, collage);
        if (score < best.score) best = {std::move(maps), score};
      }
      if (best.maps.empty()) continue;
      const double collage = refine(best.maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim, work);
      const double score = attractorDistance(best.maps, collage);
      if (score < winnerScore) {
        winnerScore = score;
        winner = std::move(best.maps);
        if (auto fit = convergedWinner()) return std::move(*fit);
        imageTree = g::KdTree3(mapImages(winner, source));
      }
    }
  }

  return finishedFit(std::move(winner), cloud, cloudTree, options, spacing, work);
}


// The cloud without its isolated points: those whose nearest point of the other half of the
// cloud (the cloud split in two at random, so that a point does not find itself) is farther than
// kIsolation times the median of these distances. Noise scattered through the cube lies far from
// the attractor's points, which lie close to each other; without it, the k-means split and the
// moments see the attractor alone, and the ranking can trim less (Ifs3FitOptions::rankTrim), so
// that a small part left out cannot hide in the trimmed share. The removed share is returned.
std::vector<glm::dvec3> withoutIsolatedPoints(std::span<const glm::dvec3> cloud, std::uint64_t seed, double& removedShare) {
  constexpr double kIsolation = 6.0;
  std::vector<std::uint32_t> index(cloud.size());
  std::iota(index.begin(), index.end(), 0u);
  g::SplitMix64 random(seed);
  for (std::size_t i = index.size(); i > 1; --i) std::swap(index[i - 1], index[random.below(i)]);
  const std::size_t half = cloud.size() / 2;
  std::vector<glm::dvec3> a, b;
  for (std::size_t i = 0; i < index.size(); ++i) (i < half ? a : b).push_back(cloud[index[i]]);
  const g::KdTree3 treeA(a), treeB(b);
  std::vector<double> distance(cloud.size());
  for (std::size_t i = 0; i < index.size(); ++i)
    distance[index[i]] = (i < half ? treeB : treeA).nearest(cloud[index[i]]).distanceSquared;
  std::vector<double> sorted = distance;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double limit = kIsolation * kIsolation * sorted[sorted.size() / 2];
  std::vector<glm::dvec3> kept;
  kept.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (!(distance[i] > limit)) kept.push_back(cloud[i]);
  removedShare = 1.0 - static_cast<double>(kept.size()) / static_cast<double>(cloud.size());
  return kept;
}

// The cloud's own spacing: the mean distance from a point to its nearest other point. Measured
// on a probe of at most 2000 points, from as many other points of the cloud (none of them in the
// probe: a point of the probe would find itself), and scaled from the probe's density to the
// cloud's as for a solid (cube root).
double estimatedPointSpacing(std::span<const glm::dvec3> cloud, std::uint64_t seed) {
  const std::size_t probeSize = std::min<std::size_t>(2000, cloud.size() / 2);
  const std::size_t querySize = std::min<std::size_t>(2000, cloud.size() - probeSize);
  const std::vector<glm::dvec3> shuffled = sample(cloud, probeSize + querySize, seed);
  const std::span<const glm::dvec3> probe(shuffled.data(), probeSize);
  const g::KdTree3 probeTree(probe);
  double sum = 0.0;
  std::size_t counted = 0;
  for (std::size_t i = probeSize; i < shuffled.size(); ++i) {
    const double d = std::sqrt(probeTree.nearest(shuffled[i]).distanceSquared);
    if (d > 0.0) sum += d, ++counted;  // a repeated point is not its own neighbour
  }
  if (counted == 0) return 0.0;
  return sum / static_cast<double>(counted) *
         std::cbrt(static_cast<double>(probeSize) / static_cast<double>(cloud.size()));
}

// One attempt's fit, and the work it did.
struct AttemptOutcome {
  Ifs3Fit fit;
  std::uint64_t work = 0;
};
using AttemptRunner = std::function<Ifs3Fit(int attempt, WorkMeter& work)>;

// What the outcomes of attempts 0, 1, ... decide, as the search takes them in turn: the fit is
// the one whose attractor lies nearest the cloud (least regeneratedDistance, the first of equal
// ones; none while every distance is infinite), and the search stops after the attempt that made
// it a converged fit (decided), else after them all.
struct AttemptChoice {
  std::optional<std::size_t> chosen;
  std::size_t attempts = 0;
  bool decided = false;
};
AttemptChoice chooseAttempt(std::span<const AttemptOutcome> outcomes) {
  AttemptChoice choice;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t attempt = 0; attempt < outcomes.size() && !choice.decided; ++attempt) {
    choice.attempts = attempt + 1;
    if (outcomes[attempt].fit.regeneratedDistance < nearest) {
      nearest = outcomes[attempt].fit.regeneratedDistance;
      choice.chosen = attempt;
    }
    choice.decided = choice.chosen && outcomes[*choice.chosen].fit.converged();
  }
  return choice;
}

// The attempts one after the other on one work meter, as a work budget needs: an attempt stops
// where the meter, counting the attempts before it, reaches the budget, and no attempt begins
// after that.
std::vector<AttemptOutcome> attemptsInTurn(const AttemptRunner& runAttempt, int attempts, std::uint64_t budget) {
  std::vector<AttemptOutcome> outcomes;
  WorkMeter work{0, budget};
  for (int attempt = 0; attempt < attempts && !(attempt > 0 && work.spent()) && !chooseAttempt(outcomes).decided; ++attempt) {
    const std::uint64_t before = work.used;
    Ifs3Fit fit = runAttempt(attempt, work);
    outcomes.push_back({std::move(fit), work.used - before});
  }
  return outcomes;
}

// The attempts on `threads` threads (the calling one and threads - 1 more), which take them in
// order, each attempt whole on one thread and on a meter of its own; the others wait while the
// first runs alone (AttemptSchedule). Without a budget an attempt's fit and work depend on its
// seed alone, never on the attempts before it (the meter is only read against a budget), so each
// outcome is the one attemptsInTurn gives. Once the attempts finished so far, in order, decide the
// fit, the later ones are cancelled: the search in turn would not make them. Returns the outcomes
// up to the first attempt not finished.
std::vector<AttemptOutcome> attemptsOnThreads(const AttemptRunner& runAttempt, int attempts, int threads) {
  std::vector<AttemptOutcome> outcomes(static_cast<std::size_t>(attempts));
  std::vector<char> finished(outcomes.size(), 0);
  const auto finishedInOrder = [&] {
    return static_cast<std::size_t>(std::find(finished.begin(), finished.end(), 0) - finished.begin());
  };
  AttemptSchedule schedule(attempts);
  std::mutex outcomesMutex;
  std::atomic<int> nextAttempt{0};
  const auto runAttempts = [&] {
    for (int attempt = nextAttempt++; attempt < attempts && !schedule.cancelled(attempt); attempt = nextAttempt++) {
      WorkMeter work;
      work.schedule = &schedule;
      work.attempt = attempt;
      try {
        Ifs3Fit fit = runAttempt(attempt, work);
        const std::lock_guard<std::mutex> lock(outcomesMutex);
        outcomes[static_cast<std::size_t>(attempt)] = {std::move(fit), work.used};
        finished[static_cast<std::size_t>(attempt)] = 1;
        const AttemptChoice choice = chooseAttempt(std::span<const AttemptOutcome>(outcomes.data(), finishedInOrder()));
        if (choice.decided) schedule.needOnly(static_cast<int>(choice.attempts));
      } catch (const AttemptCancelled&) {
      }
      // The first attempt is over: the others, if still needed, need not wait any more.
      schedule.letOthersStart();
    }
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < threads; ++t) {
    helpers.emplace_back([&] {
      schedule.waitUntilOthersMayStart();
      runAttempts();
    });
  }
  runAttempts();
  for (std::thread& helper : helpers) helper.join();
  outcomes.resize(finishedInOrder());
  return outcomes;
}

}  // namespace

Ifs3Fit fitIfs3(std::span<const glm::dvec3> fullCloud, const Ifs3FitOptions& options) {
  Ifs3Fit best;
  best.collageDistance = best.trimmedCollageDistance = best.regeneratedDistance = std::numeric_limits<double>::infinity();
  if (fullCloud.size() < static_cast<std::size_t>(20 * std::max(1, options.maps))) return best;
  double isolatedShare = 0.0;
  const std::vector<glm::dvec3> kept = withoutIsolatedPoints(fullCloud, options.seed + 3, isolatedShare);
  const std::span<const glm::dvec3> cloud =
      kept.size() >= static_cast<std::size_t>(20 * std::max(1, options.maps)) ? std::span<const glm::dvec3>(kept) : fullCloud;
  const g::KdTree3 cloudTree(cloud);
  // A fit whose collage distance is well below the cloud's own spacing has found the maps;
  // otherwise another attempt from other seeds may do better, and the best is kept.
  const double spacing = estimatedPointSpacing(cloud, options.seed + 5);
  const auto runAttempt = [&](int attempt, WorkMeter& work) {
    Ifs3FitOptions seeded = options;
    seeded.seed = options.seed + 7919 * static_cast<std::uint64_t>(attempt);
    // Attempts alternate between the two kinds of start: k-means first, the cheaper one, which
    // finds the maps when the parts are apart; the inclusion search's pool next, for
    // overlapping parts; from the second attempt on, the pool also re-seeds single maps.
    return fitOnce(cloud, cloudTree, seeded, spacing, attempt > 0, attempt % 2 == 1, work);
  };
  const int attempts = std::max(1, options.attempts);
  const int threads = std::min(attempts, options.threads > 0 ? options.threads : raster::configuredThreadCount());
  std::vector<AttemptOutcome> outcomes = options.workBudget != 0 ? attemptsInTurn(runAttempt, attempts, options.workBudget)
                                                                 : attemptsOnThreads(runAttempt, attempts, threads);
  const AttemptChoice choice = chooseAttempt(outcomes);
  if (choice.chosen) best = std::move(outcomes[*choice.chosen].fit);
  best.pointSpacing = spacing;
  best.isolatedShare = isolatedShare;
  best.attempts = static_cast<int>(choice.attempts);
  best.work = 0;
  for (std::size_t attempt = 0; attempt < choice.attempts; ++attempt) best.work += outcomes[attempt].work;
  best.stoppedByBudget = options.workBudget != 0 && best.work >= options.workBudget && !best.converged();
  // The plain collage distance on the whole cloud as given, noise included.
  if (!best.maps.empty() && cloud.size() != fullCloud.size()) {
    best.collageDistance = chamferDistance(fullCloud, mapImages(best.maps, fullCloud));
  }
  return best;
}

}  // namespace glass::course
