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

// The length of the UTF-8 character at text[at], or 0 when the bytes there are not one (a stray
// continuation byte, an overlong form, a surrogate, a cut-off sequence) or it is a C1 control
// character (U+0080 to U+009F), which terminals also act on.
std::size_t printableUtf8Length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  if (byte(at + 1) < low || byte(at + 1) > high) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (byte(at + i) < 0x80 || byte(at + i) > 0xBF) return 0;
  if (lead == 0xC2 && byte(at + 1) <= 0x9F) return 0;  // C1 control
  return length;
}

// One character of a message or source line as the terminal is shown it: printable ASCII, tabs
// and valid UTF-8 as they are; every other byte (control characters such as ESC, DEL, bytes that
// are not UTF-8) as \xHH, so that a file cannot send escape sequences to the terminal.
struct ShownCharacter {
  std::size_t bytes;  // how many bytes of the text it stands for
  std::string shown;
  int width;          // columns on the terminal (a tab is copied into the caret line instead)
};

ShownCharacter showCharacter(std::string_view text, std::size_t at) {
  const unsigned char c = static_cast<unsigned char>(text[at]);
  if ((c >= 0x20 && c < 0x7F) || c == '\t') return {1, std::string(1, text[at]), 1};
  if (c >= 0x80) {
    if (std::size_t length = printableUtf8Length(text, at); length > 0)
      return {length, std::string(text.substr(at, length)), 1};
  }
  static const char kHex[] = "0123456789abcdef";
  return {1, std::string{'\\', 'x', kHex[c >> 4], kHex[c & 15]}, 4};
}

// The source line and a caret under [column, column + length), in the style of compilers:
//     12 | tranlate 1 0 0
//        | ^~~~~~~~
// Tabs before the caret are copied so the caret lines up whatever the tab width; an escaped byte
// is underlined (or skipped) by as many columns as its escape takes.
void appendSourceExcerpt(std::string &out, SourceLocation at, int length) {
  if (!at.valid()) return;
  std::string_view text = at.file->line(at.line);
  if (text.empty() && at.line > at.file->lineCount()) return;
  std::string number = std::to_string(at.line);
  if (number.size() < 5) number.insert(0, 5 - number.size(), ' ');
  const std::size_t first = static_cast<std::size_t>(at.column < 1 ? 0 : at.column - 1);
  const std::size_t end = first + static_cast<std::size_t>(length < 1 ? 1 : length);
  std::string caret;
  bool caretStarted = false;
  out += number + " | ";
  for (std::size_t i = 0; i < text.size();) {
    const ShownCharacter c = showCharacter(text, i);
    out += c.shown;
    if (i + c.bytes <= first) {
      caret += text[i] == '\t' ? std::string(1, '\t') : std::string(static_cast<std::size_t>(c.width), ' ');
    } else if (i < end) {
      caret += caretStarted ? '~' : '^';
      caretStarted = true;
      caret.append(static_cast<std::size_t>(c.width - 1), '~');
    }
    i += c.bytes;
  }
  if (!caretStarted) {  // past the end of the line
    if (first > text.size()) caret.append(first - text.size(), ' ');
    caret += '^';
  }
  out += "\n      | " + caret + '\n';
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

std::string printable(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const ShownCharacter c = showCharacter(text, i);
    out += c.shown;
    i += c.bytes;
  }
  return out;
}

std::string formatDiagnostic(const Diagnostic &diagnostic) {
  std::string out;
  auto one = [&out](const Diagnostic &d) {
    if (d.where.file != nullptr) out += printable(describeLocation(d.where)) + ": ";
    out += severityName(d.severity);
    out += ": " + printable(d.message) + "\n";
    appendSourceExcerpt(out, d.where, d.length);
  };
  one(diagnostic);
  for (const Diagnostic &n : diagnostic.notes) one(n);
  // Messages inside included files say how the file was reached, innermost include first.
  if (diagnostic.where.file != nullptr) {
    bool first = true;
    for (SourceLocation from = diagnostic.where.file->includedFrom(); from.valid();
         from = from.file->includedFrom()) {
      out += printable(describeLocation(from)) + ": note: " +
             (first ? "'" + printable(diagnostic.where.file->path()) + "' was included from here\n"
                    : std::string("which was included from here\n"));
      first = false;
    }
  }
  return out;
}

Diagnostic &Diagnostics::error(SourceLocation at, std::string message, int length) {
  if (full()) {  // past the limit: counted nowhere, shown nowhere
    discarded_ = Diagnostic{};
    return discarded_;
  }
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
  if (full()) {
    discarded_ = Diagnostic{};
    return discarded_;
  }
  Diagnostic d;
  d.severity = Severity::Warning;
  d.where = at;
  d.length = length < 1 ? 1 : length;
  d.message = std::move(message);
  list_.push_back(std::move(d));
  return list_.back();
}

void Diagnostics::add(Diagnostic diagnostic) {
  if (full()) return;
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
