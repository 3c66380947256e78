// The course's subcommands of the `glass` command line: `glass lines`, `glass ifs` and
// `glass math`. Each takes the arguments after its name and returns the exit status: 0 success,
// 1 bad input (a file that does not parse, an impossible problem), 2 bad usage.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace glass::course {

int runLinesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int runIfsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int runMathCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int runIfs3dCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The --help texts, with examples.
std::string linesHelp();
std::string ifsHelp();
std::string mathHelp();
std::string ifs3dHelp();

// One-line summaries for the command list.
inline constexpr const char* kLinesSummary = "the line lab: the study guide's line algorithms on a grid of big pixels";
inline constexpr const char* kIfsSummary = "2D affine fractals: render an IFS file and compute its dimension";
inline constexpr const char* kIfs3dSummary = "3D affine fractals: clouds, fitting the maps, polyhedral rebuild, animation";
inline constexpr const char* kMathSummary = "the test's and exam's computations, worked step by step";

}  // namespace glass::course
