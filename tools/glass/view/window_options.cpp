#include "view/window_options.h"

#include <cstdio>
#include <cstdlib>

namespace glass::cli::view {

WindowOption takeWindowOption(const std::vector<std::string> &args, std::size_t &i, int &width, int &height,
                              std::string &problem) {
  const std::string &arg = args[i];
  if (i + 1 >= args.size()) return WindowOption::NotOne;
  if (arg == "--snapshot" || arg == "--events") {
    setenv(arg == "--snapshot" ? "GLASS_GLUT_SNAPSHOT" : "GLASS_GLUT_EVENTS", args[++i].c_str(), 1);
    return WindowOption::Taken;
  }
  if (arg != "--size") return WindowOption::NotOne;
  int w = 0, h = 0;
  char end = 0;
  if (std::sscanf(args[++i].c_str(), "%dx%d%c", &w, &h, &end) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384) {
    problem = "--size wants WIDTHxHEIGHT, such as 640x480";
    return WindowOption::Bad;
  }
  width = w;
  height = h;
  return WindowOption::Taken;
}

} // namespace glass::cli::view
