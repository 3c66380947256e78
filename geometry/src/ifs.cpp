#include "glass/geometry/ifs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "chaos_game.h"

namespace glass::geometry {

std::uint64_t ifsBaseCopies(const IteratedFunctionSystem& ifs, int depth) {
  const std::uint64_t r = ifs.maps.size();
  std::uint64_t copies = 1;
  for (int i = 0; i < depth; ++i) {
    if (r != 0 && copies > std::numeric_limits<std::uint64_t>::max() / r) {
      return std::numeric_limits<std::uint64_t>::max();
    }
    copies *= r;
  }
  return copies;
}

IfsColor partColor(const IteratedFunctionSystem& ifs, std::size_t part) {
  if (part < ifs.maps.size() && ifs.maps[part].color) return *ifs.maps[part].color;
  // Distinct hues of similar lightness, readable on black and on white.
  static constexpr std::array<IfsColor, 8> kPalette{{{0.90f, 0.22f, 0.20f},
                                                     {0.20f, 0.70f, 0.30f},
                                                     {0.25f, 0.45f, 0.90f},
                                                     {0.95f, 0.70f, 0.10f},
                                                     {0.65f, 0.35f, 0.80f},
                                                     {0.10f, 0.75f, 0.80f},
                                                     {0.90f, 0.45f, 0.65f},
                                                     {0.60f, 0.60f, 0.60f}}};
  return kPalette[part % kPalette.size()];
}

std::optional<std::vector<double>> chaosGameProbabilities(const IteratedFunctionSystem& ifs) {
  std::vector<std::optional<double>> given;
  std::vector<double> areas;
  for (const IfsMap& map : ifs.maps) {
    given.push_back(map.probability);
    areas.push_back(std::abs(map.transform.determinant()));
  }
  return chaos::probabilities(given, areas);
}

namespace {

void expandRecursively(const IteratedFunctionSystem& ifs, int depth, int part,
                       IfsMatrixStackVisitor& visitor) {
  if (depth == 0) {
    visitor.drawBase(part);
    return;
  }
  for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
    visitor.pushMatrix();
    visitor.multiplyMatrix(ifs.maps[i].transform);
    expandRecursively(ifs, depth - 1, part < 0 ? static_cast<int>(i) : part, visitor);
    visitor.popMatrix();
  }
}

// Follows the visitor calls with a stack of Affine2, to list the composites without GL.
class CompositeCollector final : public IfsMatrixStackVisitor {
 public:
  std::vector<IfsComposite> composites;

  void pushMatrix() override { stack_.push_back(stack_.back()); }
  void multiplyMatrix(const Affine2& map) override { stack_.back() = stack_.back() * map; }
  void popMatrix() override { stack_.pop_back(); }
  void drawBase(int part) override { composites.push_back({stack_.back(), part}); }

 private:
  std::vector<Affine2> stack_{Affine2::identity()};
};

}  // namespace

void expandIfs(const IteratedFunctionSystem& ifs, int depth, IfsMatrixStackVisitor& visitor) {
  expandRecursively(ifs, depth, -1, visitor);
}

std::vector<IfsComposite> ifsComposites(const IteratedFunctionSystem& ifs, int depth) {
  CompositeCollector collector;
  expandIfs(ifs, depth, collector);
  return std::move(collector.composites);
}

std::optional<glm::dvec2> fixedPoint(const Affine2& map) {
  // (I - L) x = t by Cramer's rule.
  const double a = 1.0 - map.m[0][0], b = -map.m[0][1];
  const double c = -map.m[1][0], d = 1.0 - map.m[1][1];
  const double det = a * d - b * c;
  if (std::abs(det) < 1e-12) return std::nullopt;
  const double tx = map.m[0][2], ty = map.m[1][2];
  return glm::dvec2{(tx * d - b * ty) / det, (a * ty - c * tx) / det};
}

void chaosGame(const IteratedFunctionSystem& ifs, const std::vector<double>& probabilities,
               std::uint64_t count, std::uint64_t seed,
               const std::function<void(const glm::dvec2& point, int part)>& visit) {
  const std::size_t n = ifs.maps.size();
  if (n == 0 || probabilities.size() != n) return;
  glm::dvec2 start{0.0, 0.0};
  for (const IfsMap& map : ifs.maps) {
    if (auto fixed = fixedPoint(map.transform)) {
      start = *fixed;
      break;
    }
  }
  chaos::walk(
      probabilities, start, count, seed,
      [&ifs](std::size_t i, const glm::dvec2& p) { return ifs.maps[i].transform.apply(p); }, visit);
}

std::vector<IfsPoint> chaosGamePoints(const IteratedFunctionSystem& ifs,
                                      const std::vector<double>& probabilities,
                                      std::uint64_t count, std::uint64_t seed) {
  std::vector<IfsPoint> points;
  points.reserve(count);
  chaosGame(ifs, probabilities, count, seed,
            [&points](const glm::dvec2& p, int part) { points.push_back({p, part}); });
  return points;
}

IfsWindow attractorWindow(const IteratedFunctionSystem& ifs) {
  double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin;
  double yMin = xMin, yMax = -xMin;
  auto include = [&](const glm::dvec2& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    xMin = std::min(xMin, p.x);
    xMax = std::max(xMax, p.x);
    yMin = std::min(yMin, p.y);
    yMax = std::max(yMax, p.y);
  };
  // Fixed points of the composites of up to `length` maps, at most ~4000 of them: the extreme
  // points of self-similar fractals (corners of the Sierpinski triangle, tips of the fern) are
  // usually such fixed points.
  int length = 1;
  while (length < 6 && ifsBaseCopies(ifs, length + 1) <= 4096) ++length;
  for (int depth = 1; depth <= length; ++depth) {
    for (const IfsComposite& composite : ifsComposites(ifs, depth)) {
      if (auto p = fixedPoint(composite.transform)) include(*p);
    }
  }
  if (auto probabilities = chaosGameProbabilities(ifs)) {
    chaosGame(ifs, *probabilities, 20000, 1, [&](const glm::dvec2& p, int) { include(p); });
  }
  if (!(xMin <= xMax) || !(yMin <= yMax)) return IfsWindow{};
  // A fractal that is a segment or a point still gets a window of some size.
  const double size = std::max({xMax - xMin, yMax - yMin, 1e-9});
  const double marginX = 0.1 * std::max(xMax - xMin, size * 1e-3);
  const double marginY = 0.1 * std::max(yMax - yMin, size * 1e-3);
  return {xMin - marginX, xMax + marginX, yMin - marginY, yMax + marginY};
}

IfsWindow fitWindowToAspect(const IfsWindow& window, int width, int height) {
  const double w = width <= 0 ? 1.0 : width;
  const double h = height <= 0 ? 1.0 : height;
  const double xSpan = window.xMax - window.xMin, ySpan = window.yMax - window.yMin;
  IfsWindow out = window;
  if (xSpan / w < ySpan / h) {
    // Units per pixel are larger vertically: widen x about its centre.
    const double scale = (ySpan / h) / (xSpan / w);
    const double center = (window.xMax + window.xMin) / 2.0;
    out.xMin = center - (center - window.xMin) * scale;
    out.xMax = center + (window.xMax - center) * scale;
  } else {
    const double scale = (xSpan / w) / (ySpan / h);
    const double center = (window.yMax + window.yMin) / 2.0;
    out.yMin = center - (center - window.yMin) * scale;
    out.yMax = center + (window.yMax - center) * scale;
  }
  return out;
}

}  // namespace glass::geometry
