// Numbers printed the way the study guide writes them: 2, -1/2, 1/√2, -2√2, 4/3, next to their
// decimal values. The course's answers are of the form p √k / q with small integers, and a
// student checks them against the guide; a bare 0.707107 would hide that it is 1/√2.
#pragma once

#include <string>

namespace glass::course {

// The exact form p √k / q (k square-free, q <= 24, |p| <= 240) within 1e-10 relative, or empty.
// √k / k is written 1/√k (the guide's 1/√2), and p/(m√k) in general.
std::string exactForm(double x);

// "%.6g" of x, rounded to 0 when |x| < 1e-12 (no "-0" or "6.1e-17" from cos(pi/2)).
std::string decimal(double x);

// decimal(x), followed by " (exact)" when the exact form says more than the decimal does:
// "0.707107 (1/√2)", but just "2" or "-0.5".
std::string describe(double x);

// The exact form when there is one, else the decimal: for matrices and short answers.
std::string compact(double x);

}  // namespace glass::course
