#include "glass/course/ifs3d_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "glass/geometry/deterministic_random.h"
#include "glass/geometry/ifs3d.h"
#include "glass/geometry/kd_tree.h"
#include "glass/geometry/polar_decomposition.h"
#include "glass/geometry/rotation.h"

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
  for (int k = 0; k < 3; ++k) d[k][k] = std::pow(std::max(e.values[k], floor), power);
  return e.vectors * d * glm::transpose(e.vectors);
}

// Starting orientations: the 24 rotations of the cube, each also after two fixed turns that fall
// between them, so no rotation is far from a start; and each of these with a reflection (-Q).
std::vector<glm::dmat3> startingOrientations() {
  std::vector<glm::dmat3> cube;
  const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : permutations) {
    for (int signs = 0; signs < 8; ++signs) {
      glm::dmat3 q(0.0);
      for (int c = 0; c < 3; ++c) q[c][p[c]] = (signs >> c) & 1 ? -1.0 : 1.0;
      if (glm::determinant(q) > 0.0) cube.push_back(q);
    }
  }
  const glm::dmat3 offsets[3] = {glm::dmat3(1.0), g::rotationMatrixDegrees({1.0, 1.0, 1.0}, 40.0),
                                 g::rotationMatrixDegrees({1.0, -2.0, 0.5}, 35.0)};
  std::vector<glm::dmat3> out;
  for (const glm::dmat3& offset : offsets) {
    for (const glm::dmat3& q : cube) {
      out.push_back(q * offset);
      out.push_back(-(q * offset));
    }
  }
  return out;
}

// Symmetric trimmed ICP for affine maps: moves the maps f_i so that the union of f_i(source)
// matches `target` (whose k-d tree is given), measured on `targetSample`. The least squares use
// the correspondences left after trimming, and so does the score, the trimmed symmetric Chamfer
// distance. Returns the best score seen with `maps` set to the maps that scored it.
double refine(std::vector<g::Affine3>& maps, std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
              const g::KdTree3& targetTree, std::span<const glm::dvec3> targetSample, int steps, double trim) {
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

// How far the attractor of `maps` is from the cloud: the trimmed symmetric Chamfer distance
// between `target` (a sample of the cloud) and as many chaos-game points of the maps (weights
// |det L_i|). The collage distance judges a map set by one step of the Hutchinson operator; this
// judges its attractor, and so catches what one step hides: two maps on the same part with a small
// part left out (within the trimming), or a map that is not contractive. Infinity when the
// points leave every bound.
double regeneratedDistance(const std::vector<g::Affine3>& maps, const g::KdTree3& targetTree, std::span<const glm::dvec3> target,
                           double trim, std::uint64_t seed) {
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
                   const std::vector<glm::dmat3>& orientations, double trim, std::uint64_t seed) {
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
    const double score = refine(maps, coarseSource, part, partTree, coarseTarget, 2, trim);
    candidates.push_back({score, maps[0]});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  const std::vector<glm::dvec3> fineSource = sample(cloud, 600, seed + 2);
  const std::vector<glm::dvec3> fineTarget = sample(part, 600, seed + 3);
  Candidate best{std::numeric_limits<double>::infinity(), candidates.front().map};
  for (std::size_t c = 0; c < std::min<std::size_t>(4, candidates.size()); ++c) {
    std::vector<g::Affine3> maps{candidates[c].map};
    const double score = refine(maps, fineSource, part, partTree, fineTarget, 15, trim);
    if (score < best.score) best = {score, maps[0]};
  }
  return best.map;
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

// One attempt of the whole fit, from the seed in options.
Ifs3Fit fitOnce(std::span<const glm::dvec3> cloud, const g::KdTree3& cloudTree, const Ifs3FitOptions& options) {
  const int k = std::max(1, options.maps);
  Ifs3Fit best;
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
    const double d = regeneratedDistance(maps, targetSampleTree, targetSample, options.trim, options.seed + 41);
    return std::isfinite(d) ? d : 1e6 + collage;
  };
  std::vector<g::Affine3> winner;
  double winnerScore = std::numeric_limits<double>::infinity();
  for (int start = 0; start < std::max(1, options.starts); ++start) {
    const std::uint64_t seed = options.seed + 1000 * static_cast<std::uint64_t>(start + 1);
    const std::vector<int> labels = kMeans(clusterSample, k, seed);
    std::vector<g::Affine3> maps;
    for (int part = 0; part < k; ++part) {
      std::vector<glm::dvec3> points;
      for (std::size_t i = 0; i < clusterSample.size(); ++i)
        if (labels[i] == part) points.push_back(clusterSample[i]);
      if (points.size() < 10) points = sample(clusterSample, 10, seed + static_cast<std::uint64_t>(part));
      maps.push_back(fitPart(cloud, cloudMoments, points, orientations, options.trim, seed + 7 * static_cast<std::uint64_t>(part)));
    }
    const double collage = refine(maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim);
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
  for (int round = 0; round < 2 * k; ++round) {
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
      for (const glm::dvec3& p : clusterSample) {
        if (imageTree.nearest(p).index / source.size() == static_cast<std::size_t>(part)) points.push_back(p);
      }
    }
    if (points.size() < 10) continue;
    std::vector<g::Affine3> maps = winner;
    maps[static_cast<std::size_t>(part)] =
        fitPart(cloud, cloudMoments, points, orientations, options.trim, options.seed + 31 * static_cast<std::uint64_t>(round + 1));
    const double collage = refine(maps, source, cloud, cloudTree, targetSample, options.refineSteps, options.trim);
    const double score = attractorDistance(maps, collage);
    if (score < winnerScore) {
      winnerScore = score;
      winner = maps;
    }
  }

  // A last refinement on a larger sample, then the measures on the whole cloud.
  const std::vector<glm::dvec3> largeSource = sample(cloud, 2 * perStep, options.seed + 21);
  const std::vector<glm::dvec3> largeTarget = sample(cloud, 4 * perStep, options.seed + 22);
  refine(winner, largeSource, cloud, cloudTree, largeTarget, options.refineSteps, options.trim);

  const glm::dvec3 centre = cloudMoments.mean;
  std::stable_sort(winner.begin(), winner.end(), [&](const g::Affine3& a, const g::Affine3& b) {
    const glm::dvec3 pa = a.apply(centre), pb = b.apply(centre);
    if (pa.x != pb.x) return pa.x < pb.x;
    if (pa.y != pb.y) return pa.y < pb.y;
    return pa.z < pb.z;
  });
  best.maps = winner;
  std::vector<glm::dvec3> images;
  images.reserve(cloud.size() * winner.size());
  for (const g::Affine3& map : winner)
    for (const glm::dvec3& p : cloud) images.push_back(map.apply(p));
  best.collageDistance = chamferDistance(cloud, images);
  // The same with the worst 10% each way left out, as the search scores: noise points do not
  // count against the maps.
  {
    const g::KdTree3 imageTree(images);
    std::vector<double> forward, backward;
    for (const glm::dvec3& p : images) forward.push_back(std::sqrt(cloudTree.nearest(p).distanceSquared));
    for (const glm::dvec3& p : cloud) backward.push_back(std::sqrt(imageTree.nearest(p).distanceSquared));
    best.trimmedCollageDistance = (trimmedMean(forward, options.trim).mean + trimmedMean(backward, options.trim).mean) / 2.0;
  }
  best.regeneratedDistance = regeneratedDistance(winner, cloudTree, cloud, options.trim, options.seed + 43);
  // Shares: which map's image is nearest to each cloud point.
  const g::KdTree3 imageTree(images);
  std::vector<double> counts(winner.size(), 0.0);
  for (const glm::dvec3& p : cloud) counts[imageTree.nearest(p).index / cloud.size()] += 1.0;
  for (double& c : counts) c /= static_cast<double>(cloud.size());
  best.shares = counts;
  return best;
}

}  // namespace

Ifs3Fit fitIfs3(std::span<const glm::dvec3> cloud, const Ifs3FitOptions& options) {
  Ifs3Fit best;
  best.collageDistance = best.trimmedCollageDistance = best.regeneratedDistance = std::numeric_limits<double>::infinity();
  if (cloud.size() < static_cast<std::size_t>(20 * std::max(1, options.maps))) return best;
  const g::KdTree3 cloudTree(cloud);
  // The cloud's own spacing: the mean distance from a point to its nearest other point (on a
  // sample). A fit whose collage distance is well below it has found the maps; otherwise another
  // attempt from other seeds may do better, and the best is kept.
  const std::vector<glm::dvec3> probe = sample(cloud, 2000, options.seed + 5);
  const g::KdTree3 probeTree(probe);
  double spacing = 0.0;
  for (const glm::dvec3& p : sample(cloud, 2000, options.seed + 6)) {
    const double d = std::sqrt(probeTree.nearest(p).distanceSquared);
    spacing += d > 0.0 ? d : 0.0;
  }
  spacing = spacing / 2000.0 * std::cbrt(std::min<double>(2000.0, static_cast<double>(cloud.size())) / static_cast<double>(cloud.size()));
  for (int attempt = 0; attempt < std::max(1, options.attempts); ++attempt) {
    Ifs3FitOptions seeded = options;
    seeded.seed = options.seed + 7919 * static_cast<std::uint64_t>(attempt);
    Ifs3Fit fit = fitOnce(cloud, cloudTree, seeded);
    if (fit.regeneratedDistance < best.regeneratedDistance) best = std::move(fit);
    best.pointSpacing = spacing;
    if (best.converged()) break;
  }
  best.pointSpacing = spacing;
  return best;
}

}  // namespace glass::course
