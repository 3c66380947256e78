// Scene source text and positions in it. Every token, statement and message carries a
// SourceLocation (file, 1-based line and column), so that errors read `file:line:col: message`.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace glass::scene {

class SourceFile;

struct SourceLocation {
  const SourceFile *file = nullptr;
  int line = 0;   // 1-based
  int column = 0; // 1-based, in bytes; a tab counts as one column

  bool valid() const { return file != nullptr && line > 0; }
};

// One file's text, split into lines for showing the offending line under a message. A file that
// was pulled in by `include` remembers where, so messages can say "included from".
class SourceFile {
public:
  SourceFile(std::string path, std::string text, SourceLocation includedFrom = {});

  const std::string &path() const { return path_; }
  const std::string &text() const { return text_; }
  SourceLocation includedFrom() const { return includedFrom_; }
  int lineCount() const { return static_cast<int>(lineStarts_.size()); }
  // The text of a 1-based line without its line ending; empty for a line out of range.
  std::string_view line(int number) const;

private:
  std::string path_;
  std::string text_;
  SourceLocation includedFrom_;
  std::vector<std::size_t> lineStarts_;
};

// Owns every file read while parsing one scene. Locations point into it, so it lives as long as
// the parsed program does; files never move once added.
class SourceSet {
public:
  const SourceFile &add(std::string path, std::string text, SourceLocation includedFrom = {});
  // The paths of the files read, the scene first (glass view watches them for changes).
  std::vector<std::string> paths() const {
    std::vector<std::string> result;
    for (const auto &file : files_) result.push_back(file->path());
    return result;
  }

private:
  std::deque<std::unique_ptr<SourceFile>> files_;
};

} // namespace glass::scene
