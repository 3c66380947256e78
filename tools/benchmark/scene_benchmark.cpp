// Frames per second of scene files drawn through the scene interpreter, for glass
// (scene_benchmark) and for Mesa (scene_benchmark_mesa, the same source on the scene library built
// on OSMesa). Not a test: the numbers depend on the machine.
//
// Two frames per scene. scene_NAME is what `glass render` does for one picture: a new context of
// the size asked for, the interpreter's GL calls (texture uploads and mipmaps included), and
// glReadPixels of the picture. scene_NAME_kept is what `glass view` does for each picture after
// its first: the same frame through one FrameRenderer (glass/scene/render.h), which keeps the
// context (reset with glassResetContext), the textures and the compiled definitions. Each is
// drawn once to warm up, then RUNS times; the median is reported.
//
// Usage: scene_benchmark [--size WxH] [--runs N] SCENE...
#include <glass/scene/parser.h>
#include <glass/scene/render.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace {

int usage() {
  std::cerr << "usage: scene_benchmark [--size WxH] [--runs N] SCENE...\n";
  return 2;
}

// The process's peak resident memory in MiB (Linux reports ru_maxrss in KiB).
double peakMemoryMiB() {
  rusage usage{};
  return getrusage(RUSAGE_SELF, &usage) == 0 ? static_cast<double>(usage.ru_maxrss) / 1024.0 : 0.0;
}

}  // namespace

int main(int argc, char **argv) {
  glass::scene::RenderOptions options;
  options.width = 800;
  options.height = 600;
  int runs = 7;
  std::vector<std::string> scenes;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--size" && a + 1 < argc) {
      if (std::sscanf(argv[++a], "%dx%d", &options.width, &options.height) != 2 ||
          options.width < 1 || options.height < 1 || options.width > glass::scene::kMaxFramebufferSide ||
          options.height > glass::scene::kMaxFramebufferSide)
        return usage();
    } else if (arg == "--runs" && a + 1 < argc) {
      runs = std::atoi(argv[++a]);
      if (runs < 1 || runs > 101) return usage();
    } else if (!arg.empty() && arg[0] != '-') {
      scenes.push_back(arg);
    } else {
      return usage();
    }
  }
  if (scenes.empty()) return usage();

  std::printf("resolution: %d x %d\n", options.width, options.height);
  std::printf("timing:     median of %d frames after 1 warm-up frame, ms (context, drawing, read-back;\n"
              "            _kept: the context, textures and definitions kept from frame to frame)\n",
              runs);
  for (const std::string &path : scenes) {
    glass::scene::Diagnostics diagnostics;
    const glass::scene::Program program = glass::scene::parseSceneFile(path, diagnostics);
    if (diagnostics.hasErrors()) {
      diagnostics.print(std::cerr);
      return 1;
    }
    for (const bool keep : {false, true}) {
      glass::scene::FrameRenderer kept(program);
      std::vector<double> times;
      for (int r = 0; r <= runs; ++r) {
        glass::scene::RenderedFrame frame;
        const auto start = std::chrono::steady_clock::now();
        const bool drawn = keep ? kept.render(0, options, frame, diagnostics)
                                : glass::scene::renderFrame(program, 0, options, frame, diagnostics);
        if (!drawn) {
          diagnostics.print(std::cerr);
          return 1;
        }
        const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
        if (r > 0) times.push_back(elapsed.count());  // the first frame warms up
      }
      std::sort(times.begin(), times.end());
      const double median = times[times.size() / 2];
      const std::string name = "scene_" + std::filesystem::path(path).stem().string() + (keep ? "_kept" : "");
      const std::string size = std::to_string(options.width) + "x" + std::to_string(options.height);
      std::printf("frame %-22s %8s  median %9.2f ms  (min %.2f, max %.2f; %.1f frames per second)\n",
                  name.c_str(), size.c_str(), median, times.front(), times.back(), 1000.0 / median);
      std::fflush(stdout);
    }
  }
  std::printf("peak memory: %.1f MiB\n", peakMemoryMiB());
  return 0;
}
