// Reads a scene file into a Program: lexing, parsing, checking, and loading the files the scene
// names (includes, texture images, OBJ models). Every problem goes to the Diagnostics with its
// file:line:col; the Program is usable only when no error was reported.
#pragma once

#include "glass/scene/diagnostics.h"
#include "glass/scene/program.h"

#include <string>
#include <utility>
#include <vector>

namespace glass::scene {

struct ParseOptions {
  // `--set NAME=VALUE` from the command line: replaces the value a `param` statement declares.
  // The value is numbers separated by spaces or commas.
  std::vector<std::pair<std::string, std::string>> overrides;
  // Deepest chain of `include`s before giving up (a guard besides the cycle check).
  int maxIncludeDepth = 32;
};

// Parses the scene in `path`. Returns the program; check diagnostics.hasErrors() before using it.
Program parseSceneFile(const std::string &path, Diagnostics &diagnostics,
                       const ParseOptions &options = {});

// Parses scene text that did not come from a file; `path` names it in messages and is the
// directory that relative includes and image paths start from.
Program parseSceneText(const std::string &path, const std::string &text, Diagnostics &diagnostics,
                       const ParseOptions &options = {});

} // namespace glass::scene
