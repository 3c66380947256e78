// `glass compare`: how far one picture is from another, through the image comparison library
// (tools/imagecompare, OpenImageIO), which this command loads as a module (compare_module.cpp)
// from GLASS_COMPARE_MODULE_PATH beside the program: the other commands start without it.
#include "command_registry.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <iostream>
#include <string>

namespace glass::cli {

namespace {

constexpr const char *kHelp = R"(usage: glass compare A B [--fail-psnr DB] [--fail-percent P] [--diff D.png]

Compares two pictures of the same size over their red, green and blue channels and prints
the PSNR, the mean and the largest channel error, and how many pixels are off by more than
8/255 (and their share).

options:
  --fail-psnr DB        fail (exit 1) when the PSNR is below DB decibels ("inf": must be equal)
  --fail-percent P      fail (exit 1) when more than P percent of the pixels are off
  --diff D.png          write a picture of the differences: pixels off by more than 8/255 in
                        red, smaller differences in yellow, equal pixels in dimmed grey
  -h, --help            this help

exit status: 0 within the limits, 1 beyond them, 2 bad usage or pictures that cannot be
compared (unreadable, or of different sizes)

examples:
  glass compare out/showcase.png reference_images/scenes/showcase.png
  glass compare glass.png mesa.png --fail-psnr 40 --fail-percent 0.5 --diff diff.png
)";

// The module's place: GLASS_COMPARE_MODULE_PATH from the directory of this program.
std::string modulePath() {
  char self[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length <= 0) return GLASS_COMPARE_MODULE_PATH;
  const std::string program(self, static_cast<size_t>(length));
  return program.substr(0, program.find_last_of('/') + 1) + GLASS_COMPARE_MODULE_PATH;
}

int runCompare(const std::vector<std::string> &args) {
  if (wantsHelp(args)) {
    std::cout << kHelp;
    return kExitOk;
  }
  const std::string path = modulePath();
  void *module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  using Run = int (*)(int, const char *const *);
  const auto run = module ? reinterpret_cast<Run>(dlsym(module, "glassCompareRun")) : nullptr;
  if (run == nullptr) {
    const char *reason = dlerror();  // names the file
    std::cerr << "glass compare: cannot load the image comparison module: "
              << (reason ? reason : path + " has no glassCompareRun") << "\n";
    return kExitUsage;
  }
  std::vector<const char *> argv;
  for (const std::string &arg : args) argv.push_back(arg.c_str());
  // The module prints to the same std::cout and std::cerr (one C++ runtime in the process).
  return run(static_cast<int>(argv.size()), argv.data());
}

const bool registered = registerCommand({"compare", "measure how far one picture is from another (PSNR, pixels off)", runCompare});

} // namespace

} // namespace glass::cli
