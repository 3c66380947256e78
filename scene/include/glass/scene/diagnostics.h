// Messages about a scene: `file:line:col: error: message`, then the offending line with a caret
// under the place, then notes (where a block was opened, where a file was included from).
// Parsing goes on after an error so that one run reports several, up to a limit.
#pragma once

#include "glass/scene/source.h"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace glass::scene {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation where;    // may be invalid for messages about no place in particular
  int length = 1;          // how many columns the caret line underlines
  std::string message;
  std::vector<Diagnostic> notes;

  // Adds a note pointing at another place ("block opened here").
  Diagnostic &note(SourceLocation at, std::string text, int noteLength = 1);
};

class Diagnostics {
public:
  explicit Diagnostics(int errorLimit = 20) : errorLimit_(errorLimit) {}

  // Once the limit is reached, further errors and warnings are dropped (the returned message
  // goes nowhere), so that the count and the list agree and the run stops at the limit.
  Diagnostic &error(SourceLocation at, std::string message, int length = 1);
  Diagnostic &warning(SourceLocation at, std::string message, int length = 1);
  // Adds a message made elsewhere (the lexer's, moved over in source order).
  void add(Diagnostic diagnostic);
  // Keeps the files that messages point into alive as long as the messages are, even when the
  // parsed program is gone (the parser hands over its SourceSet here).
  void keepSources(std::shared_ptr<const SourceSet> sources) { sources_.push_back(std::move(sources)); }

  int errorCount() const { return errorCount_; }
  bool hasErrors() const { return errorCount_ > 0; }
  // True once the error limit is reached: the parser stops there.
  bool full() const { return errorCount_ >= errorLimit_; }
  int errorLimit() const { return errorLimit_; }

  const std::vector<Diagnostic> &all() const { return list_; }

  // Every message in order, each with its source line and caret; ends with a count line
  // ("3 errors") when there were errors, and says when the limit cut the list short.
  std::string format() const;
  void print(std::ostream &out) const;

private:
  int errorLimit_;
  int errorCount_ = 0;
  std::vector<Diagnostic> list_;
  Diagnostic discarded_;  // what error() and warning() return past the limit
  std::vector<std::shared_ptr<const SourceSet>> sources_;
};

// One message with its source line and caret, as the command line prints it.
std::string formatDiagnostic(const Diagnostic &diagnostic);

// The text with every byte a terminal could act on (control characters such as ESC, DEL, C1
// controls, bytes that are not UTF-8) written as \xHH; tabs and valid UTF-8 stay as they are.
std::string printable(std::string_view text);

// "file:line:col" for a location (or "file" / "<unknown>" when parts are missing).
std::string describeLocation(SourceLocation at);

} // namespace glass::scene
