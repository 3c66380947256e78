// Run-time choice among the copies of a SIMD function that hwy/foreach_target.h compiled, one
// per Highway target (docs/pipeline.md, "SIMD targets"). Highway's own dispatch
// (HWY_DYNAMIC_DISPATCH) lives in libhwy, whose start-up code reads the processor's time-stamp
// counter with an instruction that valgrind cannot run; glass uses Highway's headers only and
// picks the copy here, with the processor features each target is compiled for
// (hwy/ops/set_macros-inl.h) checked in core/fast_paths.cpp.
//
// In the HWY_ONCE part of a file that includes hwy/foreach_target.h:
//   constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(F))> kF = GLASS_SIMD_FUNCTIONS(F);
//   ... chosenSimdFunction(kF)(arguments) ...
#pragma once

#include <array>

namespace glass::gl {

// The targets glass compiles SIMD code for, from the portable one up; the order of the table
// below and of the names in core/fast_paths.cpp.
enum class SimdTarget { Scalar, Ssse3, Sse4, Avx2, Avx3, Count };

// The target the SIMD code runs with: the best the processor has, or GLASS_SIMD_TARGET's.
SimdTarget chosenSimdTarget();

// Target t is compiled into this build and the processor runs it (tests run every such target).
bool simdTargetRuns(SimdTarget t);

template <typename Function>
using SimdFunctions = std::array<Function, static_cast<int>(SimdTarget::Count)>;

// The copies of F for every SimdTarget, null for a target not compiled (on other processors
// than x86, only the first, Highway's portable fallback, is).
#define GLASS_SIMD_FUNCTIONS(F)                                                           \
  {                                                                                       \
    {HWY_CHOOSE_FALLBACK(F), HWY_CHOOSE_SSSE3(F), HWY_CHOOSE_SSE4(F), HWY_CHOOSE_AVX2(F), \
     HWY_CHOOSE_AVX3(F)}                                                                  \
  }

// The copy for the chosen target.
template <typename Function>
Function chosenSimdFunction(const SimdFunctions<Function>& functions) {
  return functions[static_cast<int>(chosenSimdTarget())];
}

}  // namespace glass::gl
