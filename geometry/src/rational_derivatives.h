// Derivatives of the projected point p = H.xyz / H.w of a rational curve or patch, from the
// derivatives of its homogeneous form, by Leibniz's rule on H.xyz = w p (the quotient rule
// generalised to any order). Private to the library.
#pragma once

#include "glass/geometry/de_casteljau.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace glass::geometry::detail {

// From H, H', ..., H^(n) (homogeneous derivatives at one parameter) to p, p', ..., p^(n):
//   p^(k) = (H.xyz^(k) - sum_{i=1..k} C(k, i) w^(i) p^(k-i)) / w.
inline std::vector<glm::dvec3> projectDerivatives(const std::vector<glm::dvec4>& homogeneous) {
  std::vector<glm::dvec3> projected(homogeneous.size());
  const double w = homogeneous[0].w;
  for (std::size_t k = 0; k < homogeneous.size(); ++k) {
    glm::dvec3 numerator = glm::dvec3(homogeneous[k]);
    for (std::size_t i = 1; i <= k; ++i)
      numerator -= binomial(static_cast<int>(k), static_cast<int>(i)) * homogeneous[i].w * projected[k - i];
    projected[k] = numerator / w;
  }
  return projected;
}

// The same for a patch: from the table of mixed homogeneous derivatives
// H^(a,b) = d^(a+b) H / du^a dv^b, stored at [a * (orderV + 1) + b] for a <= orderU, b <= orderV,
// to the table of p^(a,b):
//   p^(a,b) = (H.xyz^(a,b) - sum_{(i,j) != (0,0)} C(a,i) C(b,j) w^(i,j) p^(a-i,b-j)) / w.
inline std::vector<glm::dvec3> projectMixedDerivatives(const std::vector<glm::dvec4>& homogeneous,
                                                       int orderU, int orderV) {
  const int columns = orderV + 1;
  std::vector<glm::dvec3> projected(homogeneous.size());
  const double w = homogeneous[0].w;
  for (int a = 0; a <= orderU; ++a) {
    for (int b = 0; b <= orderV; ++b) {
      glm::dvec3 numerator = glm::dvec3(homogeneous[a * columns + b]);
      for (int i = 0; i <= a; ++i) {
        for (int j = 0; j <= b; ++j) {
          if (i == 0 && j == 0) continue;
          numerator -= binomial(a, i) * binomial(b, j) * homogeneous[i * columns + j].w *
                       projected[(a - i) * columns + (b - j)];
        }
      }
      projected[a * columns + b] = numerator / w;
    }
  }
  return projected;
}

}  // namespace glass::geometry::detail
