// glass: render scene files with the glass software OpenGL, compare pictures, and run the
// course's tools. `glass --help` lists the subcommands; `glass COMMAND --help` explains one.
#include "command_registry.h"

#include <algorithm>
#include <iostream>

namespace {

void printUsage(std::ostream &out) {
  out << "usage: glass COMMAND [ARGUMENTS]\n"
         "       glass COMMAND --help     explains COMMAND, with examples\n\n"
         "commands:\n";
  for (const glass::cli::Command &command : glass::cli::allCommands()) {
    std::string name(command.name);
    name.resize(std::max<std::size_t>(name.size(), 10), ' ');
    out << "  " << name << "  " << command.summary << "\n";
  }
  out << "\nexit status: 0 success, 1 bad input (or a failed check), 2 bad usage\n"
         "documentation: docs/cli.md (the commands), docs/scene-format.md (the scene language)\n";
}

} // namespace

int main(int argc, char **argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    printUsage(std::cerr);
    return glass::cli::kExitUsage;
  }
  const std::string &name = args.front();
  if (name == "--help" || name == "-h" || name == "help") {
    if (name == "help" && args.size() > 1) {
      if (const glass::cli::Command *command = glass::cli::findCommand(args[1])) {
        return command->run({"--help"});
      }
      std::cerr << "glass: no command '" << args[1] << "'\n";
      return glass::cli::kExitUsage;
    }
    printUsage(std::cout);
    return glass::cli::kExitOk;
  }
  const glass::cli::Command *command = glass::cli::findCommand(name);
  if (command == nullptr) {
    std::cerr << "glass: unknown command '" << name << "'\n\n";
    printUsage(std::cerr);
    return glass::cli::kExitUsage;
  }
  args.erase(args.begin());
  return command->run(args);
}
