// The `glass` program's subcommands. Each subcommand lives in its own file and registers itself
// at start-up, so adding one needs no edit anywhere else:
//
//   namespace {
//   int runLines(const std::vector<std::string> &args) { ... return glass::cli::kExitOk; }
//   const bool registered = glass::cli::registerCommand(
//       {"lines", "draw a segment on a grid of big pixels with the course's algorithms", runLines});
//   }
//
// `args` are the arguments after the subcommand's name. A subcommand prints its own help for
// --help (with examples) and returns one of the exit codes below.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace glass::cli {

// Exit codes shared by every subcommand.
constexpr int kExitOk = 0;       // success
constexpr int kExitBadInput = 1; // the input (a scene, a file) is wrong, or a check failed
constexpr int kExitUsage = 2;    // the command line is wrong

struct Command {
  std::string_view name;
  std::string_view summary; // one line for `glass --help`
  int (*run)(const std::vector<std::string> &args);
};

// Adds a subcommand; returns true so that it can initialise a namespace-scope constant.
bool registerCommand(const Command &command);
// The subcommand called `name`, or null.
const Command *findCommand(std::string_view name);
// Every subcommand, sorted by name.
std::vector<Command> allCommands();

// True when args asks for help (--help or -h anywhere).
bool wantsHelp(const std::vector<std::string> &args);

} // namespace glass::cli
