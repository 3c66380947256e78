// Elementary functions with the same bits on every machine.
//
// The C library's sin, cos, atan2, exp, log2, pow and the rest are not the same functions on
// every machine: glibc picks, when a program starts, a copy compiled for the processor (with
// fused multiply-add where it has it, without where not), and the copies round differently on
// some arguments. Measured with glibc 2.36 on x86-64 (GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA
// selects the copy a processor without FMA gets): about 4 in 10,000 results of sin, cos, atan2,
// sinf and cosf differ in the last bit, and 1 in 20 million of powf. glRotatef, the GLU and GLUT
// shapes, lighting, fog and the texture level of detail all use them, so a picture could differ
// by a bit between two machines.
//
// These are computed with IEEE additions, subtractions, multiplications, divisions, square roots
// and exact operations (nearbyint, ldexp, fmod, bit access) only, in double, in a fixed order
// (the project builds with -ffp-contract=off), so they give the same bits everywhere. They are
// accurate to a few units in the last place of a double (range reduction by three-part constants,
// Taylor series to below 1e-17 of the result), so a float result computed through them is almost
// always the correctly rounded one, as the C library's is. pow is computed as exp2(y log2 x):
// its relative error grows with |y log2 x| (about 1e-14 at 100), far below a float's precision
// but not a double's last bits.
//
// sin, cos and tan reduce their argument by pi/2 in three parts, exact for |x| below about 1.6e6;
// beyond that they stay deterministic but lose accuracy (no caller comes near it).
#pragma once

namespace glass::portable {

double sin(double x);
double cos(double x);
double tan(double x);
// sin and cos of one argument, with one reduction.
void sinCos(double x, double& sine, double& cosine);
double atan(double x);
double atan2(double y, double x);
double asin(double x);
double acos(double x);
double exp(double x);
double exp2(double x);
double log2(double x);
double pow(double x, double y);

// How log2 works, for code that computes it on vector lanes with the same operations (the
// texture level of detail, texture/level_of_detail-inl.h) and must give the same bits: x = m 2^e
// with sqrt(1/2) <= m < sqrt(2) (m >= kLog2Sqrt2 is halved), s = (m - 1) / (m + 1), z = s^2,
// sum = z (sum + 1/n) for n = kLog2SeriesLastOdd, ..., 5, 3 from sum = 0 (1/n divided in
// double), ln m = 2 (s + s sum), and log2 x = e + ln m * kLog2E. The float log2 stops the series
// at kLog2FloatSeriesLastOdd: the terms left out are below 4e-14 of the result (z <= 0.0295), a
// float's last place is 6e-8 of it.
inline constexpr double kLog2E = 1.44269504088896340736;  // 1 / ln 2
inline constexpr double kLog2Sqrt2 = 1.41421356237309504880;
inline constexpr int kLog2SeriesLastOdd = 23;
inline constexpr int kLog2FloatSeriesLastOdd = 15;

// Float arguments and results: computed in double and rounded once.
inline float sin(float x) { return static_cast<float>(sin(static_cast<double>(x))); }
inline float cos(float x) { return static_cast<float>(cos(static_cast<double>(x))); }
inline float exp(float x) { return static_cast<float>(exp(static_cast<double>(x))); }
float log2(float x);  // the series to kLog2FloatSeriesLastOdd, rounded once
inline float pow(float x, float y) {
  return static_cast<float>(pow(static_cast<double>(x), static_cast<double>(y)));
}

}  // namespace glass::portable
