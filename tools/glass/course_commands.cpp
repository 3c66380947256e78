// `glass lines`, `glass ifs`, `glass ifs3d` and `glass math`: the course's exercises (docs/course.md). The
// commands themselves are in the course library (tools/course, glass/course/commands.h).
#include "command_registry.h"
#include "ifs3d_view_command.h"

#include <glass/course/commands.h>

#include <iostream>

namespace glass::cli {

namespace {

int runLines(const std::vector<std::string> &args) { return course::runLinesCommand(args, std::cout, std::cerr); }
int runIfs(const std::vector<std::string> &args) { return course::runIfsCommand(args, std::cout, std::cerr); }
// `glass ifs3d view` needs a window, which the course library does without.
int runIfs3d(const std::vector<std::string> &args) {
  if (!args.empty() && args[0] == "view") return runIfs3dView({args.begin() + 1, args.end()});
  return course::runIfs3dCommand(args, std::cout, std::cerr);
}
int runMath(const std::vector<std::string> &args) { return course::runMathCommand(args, std::cout, std::cerr); }

const bool linesRegistered = registerCommand({"lines", course::kLinesSummary, runLines});
const bool ifsRegistered = registerCommand({"ifs", course::kIfsSummary, runIfs});
const bool ifs3dRegistered = registerCommand({"ifs3d", course::kIfs3dSummary, runIfs3d});
const bool mathRegistered = registerCommand({"math", course::kMathSummary, runMath});

} // namespace

} // namespace glass::cli
