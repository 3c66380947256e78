// Elementary functions from IEEE basic operations only (portable_math.h says why).
#include "glass/geometry/portable_math.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace glass::portable {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kLn2 = 0.693147180559945309417;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// pi/2 in three parts of 33 bits each: k times the first two is exact for |k| < 2^20.
constexpr double kHalfPi1 = 1.57079632673412561417e+00;
constexpr double kHalfPi2 = 6.07710050630396597660e-11;
constexpr double kHalfPi3 = 2.02226624871116645580e-21;
// ln 2 in two parts: k times the first is exact for |k| < 2^21.
constexpr double kLn2High = 6.93147180369123816490e-01;
constexpr double kLn2Low = 1.90821492927058770002e-10;

// 1 / n!, each entry divided from the one before (at compile time, rounded to nearest).
constexpr int kFactorials = 20;
struct InverseFactorials {
  double value[kFactorials + 1];
  constexpr InverseFactorials() : value{} {
    value[0] = 1.0;
    for (int n = 1; n <= kFactorials; ++n) value[n] = value[n - 1] / n;
  }
};
constexpr InverseFactorials kInverseFactorial;

// 1 / n for odd n, the coefficients of the atan and atanh series (divided at compile time).
struct InverseOdds {
  double value[34];
  constexpr InverseOdds() : value{} {
    for (int n = 1; n < 34; n += 2) value[n] = 1.0 / n;
  }
};
constexpr InverseOdds kInverseOdd;

// The integer nearest x, ties to even, as nearbyint gives it in the default rounding mode: adding
// and subtracting 1.5 * 2^52 leaves no bits below the units. For |x| < 2^51.
double roundToInteger(double x) {
  constexpr double kShift = 0x1.8p52;
  return (x + kShift) - kShift;
}

// r 2^k for an integer k: one multiplication by the power of two when it is a normal double (as
// exact as ldexp, rounding once where the result is subnormal), ldexp otherwise.
double scaleByPowerOfTwo(double r, int k) {
  if (k < -1022 || k > 1023) return std::ldexp(r, k);
  return r * std::bit_cast<double>(static_cast<uint64_t>(k + 1023) << 52);
}

// sin r for |r| <= pi/4: r - r^3/3! + ... + r^17/17! (the next term is below 1e-19 of the sum).
double sinReduced(double r) {
  const double z = r * r;
  double sum = 0.0;
  for (int n = 17; n >= 3; n -= 2) sum = z * (sum + ((n / 2) % 2 ? -1.0 : 1.0) * kInverseFactorial.value[n]);
  return r + r * sum;
}

// cos r for |r| <= pi/4: 1 - r^2/2! + ... + r^18/18!.
double cosReduced(double r) {
  const double z = r * r;
  double sum = 0.0;
  for (int n = 18; n >= 2; n -= 2) sum = z * (sum + ((n / 2) % 2 ? -1.0 : 1.0) * kInverseFactorial.value[n]);
  return 1.0 + sum;
}

// x = k pi/2 + r with |r| <= pi/4 (about); returns r and sets quadrant to k mod 4 (0 to 3).
double reduceByHalfPi(double x, int& quadrant) {
  const double scaled = x * (2.0 / kPi);
  const double k = std::fabs(scaled) < 0x1p51 ? roundToInteger(scaled) : std::nearbyint(scaled);
  const double r = ((x - k * kHalfPi1) - k * kHalfPi2) - k * kHalfPi3;
  const double m = std::fmod(k, 4.0);  // exact; -3 to 3
  quadrant = static_cast<int>(m < 0.0 ? m + 4.0 : m);
  return r;
}

// atan t for |t| <= tan(pi/12) = 0.268: t - t^3/3 + t^5/5 - ... (to t^33, below 1e-17 of t).
double atanSeries(double t) {
  const double z = t * t;
  double sum = 0.0;
  for (int n = 33; n >= 3; n -= 2) sum = z * (sum + ((n / 2) % 2 ? -1.0 : 1.0) * kInverseOdd.value[n]);
  return t + t * sum;
}

// atan t for 0 <= t <= 1: above tan(pi/12), atan t = pi/6 + atan((sqrt(3) t - 1) / (sqrt(3) + t)).
double atanUnit(double t) {
  constexpr double kTanPiOver12 = 0.267949192431122706473;
  constexpr double kSqrt3 = 1.73205080756887729353;
  if (t <= kTanPiOver12) return atanSeries(t);
  return kPi / 6.0 + atanSeries((kSqrt3 * t - 1.0) / (kSqrt3 + t));
}

// ln m for sqrt(1/2) <= m < sqrt(2): 2 atanh s with s = (m - 1) / (m + 1), |s| <= 0.172:
// 2 (s + s^3/3 + ... + s^lastOdd/lastOdd).
double lnReduced(double m, int lastOdd) {
  const double s = (m - 1.0) / (m + 1.0);
  const double z = s * s;
  double sum = 0.0;
  for (int n = lastOdd; n >= 3; n -= 2) sum = z * (sum + kInverseOdd.value[n]);
  return 2.0 * (s + s * sum);
}

// e^r for |r| <= 0.35: 1 + r + r^2/2! + ... + r^14/14!.
double expReduced(double r) {
  double sum = 0.0;
  for (int n = 14; n >= 1; --n) sum = r * (sum + kInverseFactorial.value[n]);
  return 1.0 + sum;
}

bool isOddInteger(double y) { return std::nearbyint(y) == y && std::fmod(y, 2.0) != 0.0; }

}  // namespace

void sinCos(double x, double& sine, double& cosine) {
  if (!std::isfinite(x)) {
    sine = cosine = kNaN;
    return;
  }
  int quadrant;
  const double r = reduceByHalfPi(x, quadrant);
  const double s = sinReduced(r), c = cosReduced(r);
  switch (quadrant) {
    case 0: sine = s, cosine = c; break;
    case 1: sine = c, cosine = -s; break;
    case 2: sine = -s, cosine = -c; break;
    default: sine = -c, cosine = s; break;
  }
}

double sin(double x) {
  if (x == 0.0) return x;  // keeps the sign of zero
  double s, c;
  sinCos(x, s, c);
  return s;
}

double cos(double x) {
  double s, c;
  sinCos(x, s, c);
  return c;
}

double tan(double x) {
  if (x == 0.0) return x;
  double s, c;
  sinCos(x, s, c);
  return s / c;
}

double atan2(double y, double x) {
  if (std::isnan(x) || std::isnan(y)) return x + y;
  if (y == 0.0) return std::signbit(x) ? std::copysign(kPi, y) : y;
  if (x == 0.0) return std::copysign(kHalfPi, y);
  if (std::isinf(x)) {
    if (std::isinf(y)) return std::copysign(x > 0.0 ? kPi / 4.0 : 3.0 * kPi / 4.0, y);
    return x > 0.0 ? std::copysign(0.0, y) : std::copysign(kPi, y);
  }
  if (std::isinf(y)) return std::copysign(kHalfPi, y);
  const double a = std::fabs(y), b = std::fabs(x);
  double angle = a <= b ? atanUnit(a / b) : kHalfPi - atanUnit(b / a);
  if (x < 0.0) angle = kPi - angle;
  return std::copysign(angle, y);
}

double atan(double x) {
  if (x == 0.0 || std::isnan(x)) return x;
  return atan2(x, 1.0);
}

double asin(double x) {
  if (!(std::fabs(x) <= 1.0)) return kNaN;
  if (x == 0.0) return x;
  return atan2(x, std::sqrt((1.0 - x) * (1.0 + x)));
}

double acos(double x) {
  if (!(std::fabs(x) <= 1.0)) return kNaN;
  return atan2(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

double exp(double x) {
  if (std::isnan(x)) return x;
  if (x > 709.8) return kInfinity;
  if (x < -745.2) return 0.0;
  const double k = roundToInteger(x * kLog2E);
  const double r = (x - k * kLn2High) - k * kLn2Low;
  return scaleByPowerOfTwo(expReduced(r), static_cast<int>(k));
}

double exp2(double x) {
  if (std::isnan(x)) return x;
  if (x >= 1024.0) return kInfinity;
  if (x < -1075.0) return 0.0;
  const double k = roundToInteger(x);
  return scaleByPowerOfTwo(expReduced((x - k) * kLn2), static_cast<int>(k));
}

namespace {

// log2 x with the series of ln m to 1/lastOdd.
double log2Series(double x, int lastOdd) {
  if (std::isnan(x) || x < 0.0) return kNaN;
  if (x == 0.0) return -kInfinity;
  if (std::isinf(x)) return x;
  // x = m 2^e with sqrt(1/2) <= m < sqrt(2), from the bits (subnormals scaled up first).
  int e = 0;
  if (x < std::numeric_limits<double>::min()) {
    x *= 0x1p54;
    e = -54;
  }
  const uint64_t bits = std::bit_cast<uint64_t>(x);
  e += static_cast<int>((bits >> 52) & 0x7FF) - 1023;
  double m = std::bit_cast<double>((bits & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull);  // [1, 2)
  if (m >= kLog2Sqrt2) {
    m *= 0.5;
    ++e;
  }
  return e + lnReduced(m, lastOdd) * kLog2E;
}

}  // namespace

double log2(double x) { return log2Series(x, kLog2SeriesLastOdd); }
float log2(float x) { return static_cast<float>(log2Series(static_cast<double>(x), kLog2FloatSeriesLastOdd)); }

double pow(double x, double y) {
  if (x == 1.0 || y == 0.0) return 1.0;
  if (std::isnan(x) || std::isnan(y)) return x + y;
  const bool negative = std::signbit(x) && isOddInteger(y);
  if (x == 0.0) return std::copysign(y > 0.0 ? 0.0 : kInfinity, negative ? -1.0 : 1.0);
  if (x < 0.0 && std::nearbyint(y) != y) return kNaN;  // also y infinite: handled below first
  const double magnitude = std::fabs(x);
  if (std::isinf(y)) {
    if (magnitude == 1.0) return 1.0;
    return (magnitude < 1.0) == (y < 0.0) ? kInfinity : 0.0;
  }
  if (std::isinf(x)) return std::copysign(y > 0.0 ? kInfinity : 0.0, negative ? -1.0 : 1.0);
  const double result = exp2(y * log2(magnitude));
  return negative ? -result : result;
}

}  // namespace glass::portable
