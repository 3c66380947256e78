#include "glass/course/exact_number.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>

namespace glass::course {

namespace {

constexpr int kSquareFree[] = {1, 2, 3, 5, 6, 7, 10, 11, 13, 14, 15};

std::string sqrtSymbol(int k) { return std::string("√") + std::to_string(k); }

}  // namespace

std::string exactForm(double x) {
  if (!std::isfinite(x)) return {};
  if (std::abs(x) < 1e-12) return "0";
  for (int k : kSquareFree) {
    const double root = std::sqrt(static_cast<double>(k));
    for (int q = 1; q <= 24; ++q) {
      const double p = x * q / root;
      const double rounded = std::round(p);
      if (rounded == 0.0 || std::abs(rounded) > 240.0) continue;
      if (std::abs(p - rounded) > 1e-10 * std::max(1.0, std::abs(p))) continue;
      long long num = static_cast<long long>(rounded);
      long long den = q;
      const long long g = std::gcd(num < 0 ? -num : num, den);
      num /= g;
      den /= g;
      const std::string sign = num < 0 ? "-" : "";
      const long long a = num < 0 ? -num : num;
      if (k == 1) return sign + std::to_string(a) + (den == 1 ? "" : std::string("/") + std::to_string(den));
      // a √k / den; when den = m k, this is a / (m √k): 1/√2 rather than √2/2.
      if (den % k == 0) {
        const long long m = den / k;
        return sign + std::to_string(a) + "/" + (m == 1 ? sqrtSymbol(k) : std::string("(") + std::to_string(m) + sqrtSymbol(k) + ")");
      }
      const std::string top = (a == 1 ? "" : std::to_string(a)) + sqrtSymbol(k);
      return sign + top + (den == 1 ? "" : std::string("/") + std::to_string(den));
    }
  }
  return {};
}

std::string decimal(double x) {
  if (std::abs(x) < 1e-12) x = 0.0;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string describe(double x) {
  const std::string d = decimal(x);
  const std::string e = exactForm(x);
  // Only when it says more: 0.333333 (1/3), 0.707107 (1/√2), but not 0.25 (1/4).
  if (e.empty() || e == d || std::strtod(d.c_str(), nullptr) == x) return d;
  return d + " (" + e + ")";
}

std::string compact(double x) {
  const std::string e = exactForm(x);
  return e.empty() ? decimal(x) : e;
}

}  // namespace glass::course
