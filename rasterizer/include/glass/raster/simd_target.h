// The SIMD code of glass (the triangle walk's block rows here, the pipeline's kernels) is compiled
// for several instruction sets, Highway targets (docs/pipeline.md, "SIMD targets"), and runs
// with the best one the processor has, unless GLASS_SIMD_TARGET names another: "scalar"
// (portable code on emulated 128-bit vectors, the baseline x86-64 binary's own), "ssse3",
// "sse4", "avx2" or "avx3" (AVX-512). A name the processor cannot run, or an unknown one, is
// ignored. Every target gives the same bytes (the test image_simd_targets compares them).
// GLASS_SIMD_TARGET is read once, at the first use of SIMD code.
//
// Run-time choice among the copies of a SIMD function that hwy/foreach_target.h compiled, one
// per target: Highway's own dispatch (HWY_DYNAMIC_DISPATCH) lives in libhwy, whose start-up code
// reads the processor's time-stamp counter with an instruction that valgrind cannot run; glass
// uses Highway's headers only and picks the copy here, with the processor features each target
// is compiled for (hwy/ops/set_macros-inl.h) checked in simd_target.cpp.
//
// In the HWY_ONCE part of a file that includes hwy/foreach_target.h:
//   constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(F))> kF = GLASS_SIMD_FUNCTIONS(F);
//   ... chosenSimdFunction(kF)(arguments) ...
#pragma once

#include <array>
#include <string>

namespace glass::raster {

// The targets glass compiles SIMD code for, from the portable one up; the order of the table
// below and of the names in simd_target.cpp.
enum class SimdTarget { Scalar, Ssse3, Sse4, Avx2, Avx3, Count };

// The target the SIMD code runs with: the best the processor has, or GLASS_SIMD_TARGET's.
SimdTarget chosenSimdTarget();

// Target t is compiled into this build and the processor runs it (tests run every such target).
bool simdTargetRuns(SimdTarget t);

// The chosen target by the names above, for GL_RENDERER and the benchmark.
const char* simdTargetName();

// The targets this processor can run, by the names above, separated by spaces, "scalar" first.
std::string availableSimdTargetNames();

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

}  // namespace glass::raster
