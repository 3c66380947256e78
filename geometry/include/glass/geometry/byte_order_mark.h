// Text files saved by some Windows editors begin with the UTF-8 byte order mark, which is not part
// of their text: the readers of glass's text formats (scenes, .ifs and .ifs3 files, point clouds)
// skip it, so that their first line reads, and its columns count, as the editor shows them.
#pragma once

#include <string_view>

namespace glass::geometry {

inline constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

// The number of bytes of `text` before its text proper: 3 when it starts with the mark, else 0.
inline std::size_t byteOrderMarkLength(std::string_view text) {
  return text.starts_with(kUtf8ByteOrderMark) ? kUtf8ByteOrderMark.size() : 0;
}

}  // namespace glass::geometry
