#include "glass/course/ifs3d_residual_search.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <queue>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "glass/geometry/kd_tree.h"

namespace glass::course {

namespace g = glass::geometry;

std::vector<glm::dvec3> uncoveredPoints(std::span<const g::Affine3> maps, std::span<const glm::dvec3> source,
                                        std::span<const glm::dvec3> points, double limit) {
  std::vector<glm::dvec3> images;
  images.reserve(maps.size() * source.size());
  for (const g::Affine3& map : maps)
    for (const glm::dvec3& p : source) images.push_back(map.apply(p));
  if (images.empty()) return {points.begin(), points.end()};
  const g::KdTree3 imageTree(images);
  std::vector<glm::dvec3> out;
  for (const glm::dvec3& p : points)
    if (imageTree.nearest(p).distanceSquared > limit * limit) out.push_back(p);
  return out;
}

std::vector<std::vector<glm::dvec3>> residualClusters(std::span<const glm::dvec3> points, double link) {
  // Union-find over all pairs: the residual is a few thousand points at most.
  std::vector<std::size_t> parent(points.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const glm::dvec3 d = points[i] - points[j];
      if (glm::dot(d, d) < link * link) parent[root(i)] = root(j);
    }
  std::vector<std::vector<glm::dvec3>> clusters;
  std::vector<std::size_t> clusterOfRoot(points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t r = root(i);
    if (clusterOfRoot[r] == points.size()) {
      clusterOfRoot[r] = clusters.size();
      clusters.emplace_back();
    }
    clusters[clusterOfRoot[r]].push_back(points[i]);
  }
  std::stable_sort(clusters.begin(), clusters.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return clusters;
}

std::vector<std::size_t> mapsByOwnCover(std::span<const g::Affine3> maps, std::span<const glm::dvec3> source,
                                        std::span<const glm::dvec3> points, double reach) {
  std::vector<g::KdTree3> trees;
  for (const g::Affine3& map : maps) {
    std::vector<glm::dvec3> images;
    for (const glm::dvec3& p : source) images.push_back(map.apply(p));
    trees.emplace_back(images);
  }
  std::vector<std::size_t> ownCover(maps.size(), 0);
  for (const glm::dvec3& p : points) {
    std::size_t coveringMaps = 0, coveringMap = 0;
    for (std::size_t i = 0; i < trees.size(); ++i) {
      if (!trees[i].empty() && trees[i].nearest(p).distanceSquared <= reach * reach) {
        ++coveringMaps;
        coveringMap = i;
      }
    }
    if (coveringMaps == 1) ++ownCover[coveringMap];
  }
  std::vector<std::size_t> order(maps.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ownCover[a] < ownCover[b]; });
  return order;
}

namespace {

constexpr std::size_t kProbes = 12, kKept = 120;
constexpr double kCoarseTolerance = 1.5;
// Ratios from the smallest part the course's systems have (0.3 of the cloud, shrunk by a quarter
// on an axis) to the largest (0.6, stretched by a quarter); the hill climbing stretches between
// them.
constexpr double kRatios[] = {0.25, 0.31, 0.38, 0.46, 0.55, 0.66};

// A centre's best map of the coarse vote: x -> centre + ratio orientation (x - mean).
struct Candidate {
  double score;
  glm::dvec3 centre;
  std::size_t ratioIndex;  // in kRatios
  std::size_t orientation;
  bool scored;  // false: left out by the vote's bound, its score not below it

  double ratio() const { return kRatios[ratioIndex]; }
};

// The coarse vote at one of kRatios: a candidate map's score is how far the pre-images of the
// residual probes and the images of the cloud probes fall from the cloud, each beyond the
// tolerance and up to the cap, summed.
class RatioVote {
 public:
  RatioVote(const ResidualSearch& search, std::span<const glm::dvec3> probes, std::span<const glm::dvec3> residualProbes,
            std::size_t ratioIndex, double tolerance, double cap)
      : grid_(*search.grid), ratioIndex_(ratioIndex), tolerance_(tolerance), cap_(cap), probeCount_(probes.size()),
        residualCount_(residualProbes.size()) {
    // Per orientation: the probes' offsets under the map, the residual probes' pre-images before
    // the centre's share, and the inverse that takes the centre back.
    const std::size_t orientations = search.orientations.size();
    const double ratio = kRatios[ratioIndex];
    forward_.resize(orientations * probes.size());
    backward_.resize(orientations * residualProbes.size());
    inverses_.resize(orientations);
    for (std::size_t q = 0; q < orientations; ++q) {
      inverses_[q] = glm::transpose(search.orientations[q]) / ratio;  // orientations are orthogonal
      for (std::size_t j = 0; j < probes.size(); ++j)
        forward_[q * probes.size() + j] = ratio * (search.orientations[q] * (probes[j] - search.cloudMean));
      for (std::size_t j = 0; j < residualProbes.size(); ++j)
        backward_[q * residualProbes.size() + j] = search.cloudMean + inverses_[q] * residualProbes[j];
    }
  }

  // The best orientation at `centre` (the least score, the first of equal ones) when its score is
  // below `bound`; otherwise a candidate that is not scored. A sum stops once it reaches the
  // best score so far, which starts at the bound: its terms are not negative.
  Candidate best(const glm::dvec3& centre, double bound) const {
    Candidate best{bound, centre, ratioIndex_, 0, false};
    for (std::size_t q = 0; q < inverses_.size(); ++q) {
      const glm::dvec3 back = inverses_[q] * centre;
      double score = 0.0;
      for (std::size_t j = 0; j < residualCount_ && score < best.score; ++j)
        score += std::clamp(grid_.at(backward_[q * residualCount_ + j] - back) - tolerance_, 0.0, cap_);
      for (std::size_t j = 0; j < probeCount_ && score < best.score; ++j)
        score += std::clamp(grid_.at(centre + forward_[q * probeCount_ + j]) - tolerance_, 0.0, cap_);
      if (score < best.score) best = {score, centre, ratioIndex_, q, true};
    }
    if (!best.scored) best.score = std::numeric_limits<double>::infinity();
    return best;
  }

 private:
  const DistanceGrid& grid_;
  std::size_t ratioIndex_;
  double tolerance_, cap_;
  std::size_t probeCount_, residualCount_;
  std::vector<glm::dvec3> forward_, backward_;
  std::vector<glm::dmat3> inverses_;
};

// The centres of the grid, at each ratio, whose image can hold the residual probes (reach) with
// the best orientation of each, in the order ratio, z, y, x.
//
// Scoring every orientation of every centre in full is the search's whole cost, and only the
// first few hundred candidates matter (the kKept kept apart from each other lie among the first
// few hundred of tens of thousands); so the vote keeps the voteDepth-th least score so far as a
// bound, and a centre whose every orientation sums to no less is left out, unscored. The bound
// only falls, so every centre whose score is below its final value was scored: the candidates,
// sorted, begin exactly as the sorted candidates of a vote without a bound, as far as the
// returned bound. Past it, `scoreLeftOut` scores the rest.
struct CoarseVote {
  std::vector<Candidate> candidates;
  std::vector<RatioVote> votes;  // per ratio
  double bound = std::numeric_limits<double>::infinity();

  void scoreLeftOut() {
    for (Candidate& c : candidates) {
      if (c.scored) continue;
      c = votes[c.ratioIndex].best(c.centre, std::numeric_limits<double>::infinity());
    }
    bound = std::numeric_limits<double>::infinity();
  }
};

// The vote's bound, shared by the threads that vote: the voteDepth-th least of the scores found
// so far. Only the centres that come below the bound are scored, a few thousand of tens of
// thousands once it has fallen, so a lock on the ranking costs little.
class SharedBound {
 public:
  explicit SharedBound(std::size_t depth) : depth_(depth) {}
  double current() const { return bound_.load(std::memory_order_relaxed); }
  double last() const { return bound_.load(); }
  void add(double score) {
    if (depth_ == 0) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    ranked_.push(score);
    if (ranked_.size() > depth_) ranked_.pop();
    if (ranked_.size() == depth_) bound_.store(ranked_.top(), std::memory_order_relaxed);
  }

 private:
  std::size_t depth_;
  std::mutex mutex_;
  std::priority_queue<double> ranked_;  // the depth_ least scores so far
  std::atomic<double> bound_{std::numeric_limits<double>::infinity()};
};

CoarseVote coarseVote(const ResidualSearch& search, std::span<const glm::dvec3> probes, std::span<const glm::dvec3> residualProbes,
                      double radius, double tolerance, double cap) {
  const DistanceGrid& grid = *search.grid;
  const double h = grid.cell();
  CoarseVote vote;
  for (std::size_t r = 0; r < std::size(kRatios); ++r) vote.votes.emplace_back(search, probes, residualProbes, r, tolerance, cap);
  // A task per ratio and z slice of the grid, taken in turn by the threads; the candidates are
  // joined in task order, the order of the vote on one thread, whatever thread voted each.
  const std::size_t slices = static_cast<std::size_t>(grid.size(2)), tasks = vote.votes.size() * slices;
  std::vector<std::vector<Candidate>> taskCandidates(tasks);
  SharedBound bound(search.voteDepth);
  std::atomic<std::size_t> nextTask{0};
  const auto voteTasks = [&] {
    for (std::size_t task = nextTask++; task < tasks; task = nextTask++) {
      const std::size_t r = task / slices;
      const int z = static_cast<int>(task % slices);
      const double ratio = kRatios[r];
      for (int y = 0; y < grid.size(1); ++y)
        for (int x = 0; x < grid.size(0); ++x) {
          const glm::dvec3 centre = grid.lo() + (glm::dvec3(x, y, z) + 0.5) * h;
          // The residual lies in the image, so within the image's reach of its centre.
          bool reachable = true;
          for (const glm::dvec3& p : residualProbes) reachable = reachable && glm::length(p - centre) <= 1.3 * ratio * radius + h;
          if (!reachable) continue;
          const Candidate best = vote.votes[r].best(centre, bound.current());
          taskCandidates[task].push_back(best);
          if (best.scored) bound.add(best.score);
        }
    }
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < std::min<int>(search.threads, static_cast<int>(tasks)); ++t) helpers.emplace_back(voteTasks);
  voteTasks();
  for (std::thread& helper : helpers) helper.join();
  for (const std::vector<Candidate>& candidates : taskCandidates) vote.candidates.insert(vote.candidates.end(), candidates.begin(), candidates.end());
  vote.bound = bound.last();
  return vote;
}

// Up to kKept of the sorted candidates, each apart from those before it in centre or in
// orientation; nullopt when the list runs past `bound` (its order there is not known) first.
std::optional<std::vector<Candidate>> keptApart(std::span<const Candidate> sorted, double bound, const ResidualSearch& search, double h) {
  std::vector<Candidate> kept;
  for (const Candidate& c : sorted) {
    if (kept.size() == kKept) break;
    if (!(c.score < bound)) return std::nullopt;
    const bool near = std::any_of(kept.begin(), kept.end(), [&](const Candidate& other) {
      if (glm::length(other.centre - c.centre) >= 2.0 * h || std::abs(other.ratio() - c.ratio()) > 0.1) return false;
      const glm::dmat3 d = search.orientations[other.orientation] - search.orientations[c.orientation];
      double largest = 0.0;
      for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) largest = std::max(largest, std::abs(d[col][row]));
      return largest < 0.5;
    });
    if (!near) kept.push_back(c);
  }
  return kept;
}

}  // namespace

std::vector<g::Affine3> residualCandidates(const ResidualSearch& search, std::span<const glm::dvec3> residual, std::size_t wanted) {
  constexpr double kSameMap = 0.05;  // largest entry difference
  if (residual.size() < 8 || search.cloudProbes.empty()) return {};
  const DistanceGrid& grid = *search.grid;
  const double h = grid.cell(), cap = 3.0 * h;
  // The coarse votes forgive what the coarse steps of orientation, ratio and centre miss by
  // (starting orientations up to about 15 degrees from the true one).
  const double tolerance = kCoarseTolerance * h;
  const glm::dvec3 mean = search.cloudMean;
  const std::vector<glm::dvec3> probes = spreadPoints(search.cloudProbes, kProbes);
  const std::vector<glm::dvec3> residualProbes = spreadPoints(residual, kProbes);
  double radius = 0.0;  // of the cloud about its mean
  for (const glm::dvec3& p : search.cloudProbes) radius = std::max(radius, glm::length(p - mean));

  CoarseVote vote = coarseVote(search, probes, residualProbes, radius, tolerance, cap);
  const auto byScore = [](const Candidate& a, const Candidate& b) { return a.score < b.score; };
  std::stable_sort(vote.candidates.begin(), vote.candidates.end(), byScore);
  std::optional<std::vector<Candidate>> keptCandidates = keptApart(vote.candidates, vote.bound, search, h);
  if (!keptCandidates) {  // the kept lie deeper than the vote scored: the rest scored, the same choice
    vote.scoreLeftOut();
    std::stable_sort(vote.candidates.begin(), vote.candidates.end(), byScore);
    keptCandidates = keptApart(vote.candidates, vote.bound, search, h);
  }
  const std::vector<Candidate>& kept = *keptCandidates;

  // The kept candidates improved on finer probes.
  const std::vector<glm::dvec3> fineProbes = spreadPoints(search.cloudProbes, 4 * kProbes);
  const std::vector<glm::dvec3> fineResidual = spreadPoints(residual, 3 * kProbes);
  const GridScore score = [&](const glm::dmat3& linear, const glm::dvec3& centre) {
    const double determinant = glm::determinant(linear);
    if (!(std::abs(determinant) > 1e-12)) return std::numeric_limits<double>::infinity();
    const glm::dmat3 inverse = glm::inverse(linear);
    double sum = 0.0;
    for (const glm::dvec3& p : fineProbes) sum += std::min(grid.at(centre + linear * (p - mean)), cap);
    const double forwardMean = sum / static_cast<double>(fineProbes.size());
    sum = 0.0;
    for (const glm::dvec3& r : fineResidual) sum += std::min(grid.at(mean + inverse * (r - centre)), cap);
    return forwardMean + sum / static_cast<double>(fineResidual.size());
  };
  struct Climbed {
    double score;
    g::Affine3 map;
  };
  std::vector<Climbed> climbed;
  for (Candidate c : kept) {
    const glm::dmat3 linear = climbOnGrid(score, c.ratio() * search.orientations[c.orientation], c.centre, h);
    climbed.push_back({score(linear, c.centre), g::Affine3::fromParts(linear, c.centre - linear * mean)});
  }
  std::stable_sort(climbed.begin(), climbed.end(), [](const Climbed& a, const Climbed& b) { return a.score < b.score; });
  // Climbs from nearby starts often end on the same map: those are one candidate.
  std::vector<g::Affine3> out;
  for (const Climbed& c : climbed) {
    if (out.size() == wanted) break;
    if (std::none_of(out.begin(), out.end(), [&](const g::Affine3& o) { return g::Affine3::maxDifference(o, c.map) < kSameMap; })) out.push_back(c.map);
  }
  return out;
}

}  // namespace glass::course
