// Prints the SIMD targets glass's kernels can run with on this processor, separated by spaces,
// the reference ("scalar") first; with --chosen, the target glass picks (GLASS_SIMD_TARGET
// decides when it names one of them). For the test image_simd_targets (fast_paths.cmake).
#include <cstdio>
#include <cstring>

#include "core/fast_paths.h"

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--chosen") == 0) {
    std::printf("%s\n", glass::gl::simdTargetName());
  } else if (argc == 1) {
    std::printf("%s\n", glass::gl::availableSimdTargetNames().c_str());
  } else {
    std::fprintf(stderr, "usage: simd_target_names [--chosen]\n");
    return 2;
  }
  return 0;
}
