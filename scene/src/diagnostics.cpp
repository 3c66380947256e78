#include "glass/scene/diagnostics.h"

#include <ostream>

namespace glass::scene {

namespace {

const char *severityName(Severity severity) {
  switch (severity) {
  case Severity::Error: return "error";
  case Severity::Warning: return "warning";
  case Severity::Note: return "note";
  }
  return "error";
}

// The source line and a caret under [column, column + length), in the style of compilers:
//     12 | tranlate 1 0 0
//        | ^~~~~~~~
// Tabs before the caret are copied so the caret lines up whatever the tab width.
void appendSourceExcerpt(std::string &out, SourceLocation at, int length) {
  if (!at.valid()) return;
  std::string_view text = at.file->line(at.line);
  if (text.empty() && at.line > at.file->lineCount()) return;
  std::string number = std::to_string(at.line);
  if (number.size() < 5) number.insert(0, 5 - number.size(), ' ');
  out += number + " | ";
  out += text;
  out += "\n      | ";
  int column = at.column < 1 ? 1 : at.column;
  for (int i = 1; i < column; ++i) {
    std::size_t index = static_cast<std::size_t>(i - 1);
    out += (index < text.size() && text[index] == '\t') ? '\t' : ' ';
  }
  out += '^';
  int available = static_cast<int>(text.size()) - column;
  int tail = length - 1;
  if (tail > available) tail = available;
  for (int i = 0; i < tail; ++i) out += '~';
  out += '\n';
}

} // namespace

Diagnostic &Diagnostic::note(SourceLocation at, std::string text, int noteLength) {
  Diagnostic n;
  n.severity = Severity::Note;
  n.where = at;
  n.length = noteLength;
  n.message = std::move(text);
  notes.push_back(std::move(n));
  return *this;
}

std::string describeLocation(SourceLocation at) {
  if (at.file == nullptr) return "<unknown>";
  std::string out = at.file->path();
  if (at.line > 0) {
    out += ':';
    out += std::to_string(at.line);
    out += ':';
    out += std::to_string(at.column);
  }
  return out;
}

std::string formatDiagnostic(const Diagnostic &diagnostic) {
  std::string out;
  auto one = [&out](const Diagnostic &d) {
    if (d.where.file != nullptr) out += describeLocation(d.where) + ": ";
    out += severityName(d.severity);
    out += ": " + d.message + "\n";
    appendSourceExcerpt(out, d.where, d.length);
  };
  one(diagnostic);
  for (const Diagnostic &n : diagnostic.notes) one(n);
  // Messages inside included files say how the file was reached, innermost include first.
  if (diagnostic.where.file != nullptr) {
    bool first = true;
    for (SourceLocation from = diagnostic.where.file->includedFrom(); from.valid();
         from = from.file->includedFrom()) {
      out += describeLocation(from) + ": note: " +
             (first ? "'" + diagnostic.where.file->path() + "' was included from here\n"
                    : std::string("which was included from here\n"));
      first = false;
    }
  }
  return out;
}

Diagnostic &Diagnostics::error(SourceLocation at, std::string message, int length) {
  ++errorCount_;
  Diagnostic d;
  d.severity = Severity::Error;
  d.where = at;
  d.length = length < 1 ? 1 : length;
  d.message = std::move(message);
  list_.push_back(std::move(d));
  return list_.back();
}

Diagnostic &Diagnostics::warning(SourceLocation at, std::string message, int length) {
  Diagnostic d;
  d.severity = Severity::Warning;
  d.where = at;
  d.length = length < 1 ? 1 : length;
  d.message = std::move(message);
  list_.push_back(std::move(d));
  return list_.back();
}

void Diagnostics::add(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::Error) ++errorCount_;
  list_.push_back(std::move(diagnostic));
}

std::string Diagnostics::format() const {
  std::string out;
  for (const Diagnostic &d : list_) out += formatDiagnostic(d);
  if (errorCount_ > 0) {
    out += std::to_string(errorCount_) + (errorCount_ == 1 ? " error" : " errors");
    if (full()) out += " (stopped at the limit of " + std::to_string(errorLimit_) + ")";
    out += "\n";
  }
  return out;
}

void Diagnostics::print(std::ostream &out) const { out << format(); }

} // namespace glass::scene
