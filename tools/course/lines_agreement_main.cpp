// lines_agreement [SEGMENTS [GRID [SEED]]]: the share of random segments whose squares, for each
// of the study guide's line algorithms, equal those GL_LINES draws. Built twice from this source:
// against glass (lines_agreement) and against Mesa (lines_agreement_mesa), so the same segments
// are compared with both.
#include <glass/context.h>

#include <GL/gl.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "glass/course/line_agreement.h"

int main(int argc, char** argv) {
  const long segments = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 10000;
  const long grid = argc > 2 ? std::strtol(argv[2], nullptr, 10) : 32;
  const long seed = argc > 3 ? std::strtol(argv[3], nullptr, 10) : 1;
  if (argc > 4 || segments < 1 || grid < 2 || grid > 4096 || seed < 0) {
    std::fprintf(stderr, "usage: %s [SEGMENTS >= 1 [GRID 2..4096 [SEED >= 0]]]\n", argv[0]);
    return 2;
  }
  GlassContext* context = glassCreateContext(static_cast<int>(grid), static_cast<int>(grid));
  if (context == nullptr || !glassMakeCurrent(context)) {
    std::fprintf(stderr, "%s: cannot create a GL context\n", argv[0]);
    return 1;
  }
  const auto results = glass::course::measureGlAgreement(static_cast<std::size_t>(segments), static_cast<int>(grid),
                                                         static_cast<std::uint64_t>(seed));
  const char* vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = std::string(vendor ? vendor : "?") + " " + (renderer ? renderer : "?");
  std::fputs(glass::course::formatAgreement(results, name, static_cast<int>(grid)).c_str(), stdout);
  glassDestroyContext(context);
  return 0;
}
