// The choice of SIMD target (glass/raster/simd_target.h).
#include "glass/raster/simd_target.h"

#include <hwy/detect_targets.h>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <string>

namespace glass::raster {
namespace {

struct TargetInfo {
  const char* name;  // as GLASS_SIMD_TARGET takes it
  int64_t highwayTarget;
};
// Indexed by SimdTarget. The portable copy is Highway's static target: on a baseline x86-64 build
// HWY_SCALAR (one lane per vector, plain C++) or EMU128, whichever this Highway compiles.
constexpr int64_t kFallback = HWY_STATIC_TARGET;
constexpr TargetInfo kTargets[] = {
    {"scalar", kFallback}, {"ssse3", HWY_SSSE3}, {"sse4", HWY_SSE4},
    {"avx2", HWY_AVX2},    {"avx3", HWY_AVX3},
};
static_assert(std::size(kTargets) == static_cast<size_t>(SimdTarget::Count));

#if HWY_ARCH_X86 && (defined(__GNUC__) || defined(__clang__))
// F16C from CPUID leaf 1 (ECX bit 29): clang 14's __builtin_cpu_supports does not know "f16c".
bool hasF16c() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  return __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_F16C) != 0;
}
#endif

// The processor has the instructions Highway compiles target t with (HWY_TARGET_STR in
// hwy/ops/set_macros-inl.h); __builtin_cpu_supports also checks that the operating system saves
// the AVX and AVX-512 registers.
bool processorRuns(SimdTarget t) {
#if HWY_ARCH_X86 && (defined(__GNUC__) || defined(__clang__))
  const bool ssse3 = __builtin_cpu_supports("ssse3");
  const bool sse4 = ssse3 && __builtin_cpu_supports("sse4.1") && __builtin_cpu_supports("sse4.2") &&
                    __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("aes");
  const bool avx2 = sse4 && __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") &&
                    __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
                    __builtin_cpu_supports("fma") && hasF16c();
  const bool avx3 = avx2 && __builtin_cpu_supports("avx512f") &&
                    __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
                    __builtin_cpu_supports("avx512bw");
  switch (t) {
    case SimdTarget::Scalar: return true;
    case SimdTarget::Ssse3: return ssse3;
    case SimdTarget::Sse4: return sse4;
    case SimdTarget::Avx2: return avx2;
    case SimdTarget::Avx3: return avx3;
    case SimdTarget::Count: break;
  }
  return false;
#else
  return t == SimdTarget::Scalar;
#endif
}

// Compiled in (HWY_TARGETS of this build) and runnable here.
bool available(SimdTarget t) {
  const int64_t target = kTargets[static_cast<int>(t)].highwayTarget;
  return (HWY_TARGETS & target) != 0 && processorRuns(t);
}

}  // namespace

SimdTarget chosenSimdTarget() {
  // Once: every draw of the process runs with the same target.
  static const SimdTarget chosen = [] {
    const char* text = std::getenv("GLASS_SIMD_TARGET");
    int best = 0;
    for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
      const auto target = static_cast<SimdTarget>(t);
      if (!available(target)) continue;
      // A target the processor lacks would fault at its first instruction: GLASS_SIMD_TARGET
      // naming one is ignored, and simdTargetName() tells which target runs instead.
      if (text != nullptr && std::strcmp(text, kTargets[t].name) == 0) return target;
      best = t;
    }
    return static_cast<SimdTarget>(best);
  }();
  return chosen;
}

bool simdTargetRuns(SimdTarget t) { return available(t); }

const char* simdTargetName() { return kTargets[static_cast<int>(chosenSimdTarget())].name; }

std::string availableSimdTargetNames() {
  std::string names;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    if (!available(static_cast<SimdTarget>(t))) continue;
    if (!names.empty()) names += ' ';
    names += kTargets[t].name;
  }
  return names;
}

}  // namespace glass::raster
