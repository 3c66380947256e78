#include "chaos_game.h"

#include <cmath>

namespace glass::geometry::chaos {

std::optional<std::vector<double>> probabilities(std::span<const std::optional<double>> given,
                                                 std::span<const double> absDeterminants) {
  const std::size_t n = given.size();
  if (n == 0 || absDeterminants.size() != n) return std::nullopt;
  std::size_t count = 0;
  for (const auto& p : given) count += p.has_value() ? 1 : 0;
  if (count != 0 && count != n) return std::nullopt;

  std::vector<double> weights(n);
  if (count == n) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!(*given[i] >= 0.0)) return std::nullopt;  // negative or NaN
      weights[i] = *given[i];
    }
  } else {
    double largest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      weights[i] = absDeterminants[i];
      largest = std::max(largest, weights[i]);
    }
    // All maps flatten: every part is lower-dimensional; share evenly.
    const double floor = largest > 0.0 ? largest / 100.0 : 1.0;
    for (double& w : weights) w = std::max(w, floor);
  }
  double total = 0.0;
  for (double w : weights) total += w;
  if (!(total > 0.0) || !std::isfinite(total)) return std::nullopt;
  for (double& w : weights) w /= total;
  return weights;
}

}  // namespace glass::geometry::chaos
