#include "command_registry.h"

#include <algorithm>

namespace glass::cli {

namespace {

// A function-local list, so that registrations from other files' static initialisers find it
// constructed whatever order those initialisers run in.
std::vector<Command> &registry() {
  static std::vector<Command> commands;
  return commands;
}

} // namespace

bool registerCommand(const Command &command) {
  registry().push_back(command);
  return true;
}

const Command *findCommand(std::string_view name) {
  for (const Command &command : registry()) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

std::vector<Command> allCommands() {
  std::vector<Command> commands = registry();
  std::sort(commands.begin(), commands.end(), [](const Command &a, const Command &b) { return a.name < b.name; });
  return commands;
}

bool wantsHelp(const std::vector<std::string> &args) {
  return std::any_of(args.begin(), args.end(), [](const std::string &a) { return a == "--help" || a == "-h"; });
}

} // namespace glass::cli
