#include "glass/scene/source.h"

#include "glass/geometry/byte_order_mark.h"

namespace glass::scene {

SourceFile::SourceFile(std::string path, std::string text, SourceLocation includedFrom)
    : path_(std::move(path)), text_(std::move(text)), includedFrom_(includedFrom) {
  text_.erase(0, geometry::byteOrderMarkLength(text_));
  lineStarts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\n') lineStarts_.push_back(i + 1);
  }
  // A final newline does not open a line of its own.
  if (lineStarts_.size() > 1 && lineStarts_.back() == text_.size()) lineStarts_.pop_back();
}

std::string_view SourceFile::line(int number) const {
  if (number < 1 || number > lineCount()) return {};
  std::size_t begin = lineStarts_[static_cast<std::size_t>(number - 1)];
  std::size_t end = text_.find('\n', begin);
  if (end == std::string::npos) end = text_.size();
  if (end > begin && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(begin, end - begin);
}

const SourceFile &SourceSet::add(std::string path, std::string text, SourceLocation includedFrom) {
  files_.push_back(std::make_unique<SourceFile>(std::move(path), std::move(text), includedFrom));
  return *files_.back();
}

} // namespace glass::scene
