// The byte copies that stand in for the conversions of client pixels (texture/client_pixels.h):
// glReadPixels of a colour buffer, texture images of RGBA bytes and glDrawPixels of unsigned bytes
// copy bytes where the general path would take each byte b as b / 255 and convert it back. Each
// copy must write exactly what the conversion writes.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "fragment/color_conversion.h"
#include "texture/client_pixels.h"
#include "texture/texture_image.h"

namespace {

constexpr uint8_t kUntouched = 0xEE;

}  // namespace

// glReadPixels copies stored bytes for GL_UNSIGNED_BYTE colour formats without luminance
// (packByteColorSpan) instead of taking each byte b as b / 255 and converting it back. The copy
// must write exactly what the conversion writes: every byte value, in every format it takes,
// with padding, row length and skips that place the span inside a larger block.
TEST_CASE("pack_byte_color_span_matches_floats") {
  using glass::gl::PixelLayout;
  std::vector<uint8_t> bytes(256 * 4);
  for (int i = 0; i < 256; ++i)
    for (int k = 0; k < 4; ++k) bytes[static_cast<size_t>(i) * 4 + k] = static_cast<uint8_t>((i + 67 * k) & 255);
  std::vector<float> floats(bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) floats[i] = static_cast<float>(bytes[i]) / 255.0f;

  const GLenum formats[] = {GL_RGBA, GL_BGRA, GL_RGB, GL_BGR, GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
  for (const GLenum format : formats) {
    for (const int alignment : {1, 2, 4, 8}) {
      PixelLayout layout{};
      layout.alignment = alignment;
      layout.rowLength = 300;
      layout.skipPixels = 3;
      layout.skipRows = 1;
      CAPTURE(format);
      CAPTURE(alignment);
      std::vector<uint8_t> copied(300 * 4 * 4 + 64, kUntouched), converted = copied;
      const int width = 260, column = 2, row = 1;
      REQUIRE(glass::gl::packByteColorSpan(bytes.data(), 256, width, column, row, format,
                                           GL_UNSIGNED_BYTE, layout, copied.data()));
      glass::gl::packColorSpan(floats.data(), 256, width, column, row, format, GL_UNSIGNED_BYTE,
                               layout, glass::gl::LuminancePacking::Sum, converted.data());
      CHECK(copied == converted);
    }
  }
  // What it does not take is left to the conversion, with nothing written.
  PixelLayout layout{};
  std::vector<uint8_t> untouched(64, kUntouched), buffer = untouched;
  CHECK_FALSE(glass::gl::packByteColorSpan(bytes.data(), 4, 4, 0, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                                           layout, buffer.data()));
  CHECK_FALSE(glass::gl::packByteColorSpan(bytes.data(), 4, 4, 0, 0, GL_RGBA, GL_UNSIGNED_SHORT,
                                           layout, buffer.data()));
  CHECK_FALSE(glass::gl::packByteColorSpan(bytes.data(), 4, 4, 0, 0, GL_LUMINANCE_ALPHA,
                                           GL_UNSIGNED_BYTE, layout, buffer.data()));
  CHECK(buffer == untouched);
}

// Texture images of GL_RGBA bytes in an RGBA texture are copied row by row (unpackTexels) instead
// of each byte b becoming b / 255 and being stored back: the copy must be what the conversion
// gives, for every byte value, with padding, row length and skips.
TEST_CASE("unpack_rgba_bytes_copies_conversion") {
  using glass::gl::PixelLayout;
  const int width = 256, height = 3;
  for (const int alignment : {1, 2, 4, 8}) {
    CAPTURE(alignment);
    PixelLayout layout{};
    layout.alignment = alignment;
    layout.rowLength = 261;
    layout.skipPixels = 2;
    layout.skipRows = 1;
    std::vector<uint8_t> client(static_cast<size_t>(261) * 4 * (height + 2) + 64);
    for (size_t i = 0; i < client.size(); ++i) client[i] = static_cast<uint8_t>((i / 4 + 67 * (i % 4) + alignment) & 255);
    std::vector<uint8_t> copied;
    glass::gl::unpackTexels(client.data(), width, height, GL_RGBA, GL_UNSIGNED_BYTE, layout,
                            glass::gl::BaseFormat::RGBA, copied);
    std::vector<uint8_t> converted(static_cast<size_t>(width) * height * 4);
    std::vector<float> rgba(static_cast<size_t>(width) * 4);
    for (int j = 0; j < height; ++j) {
      glass::gl::unpackColorRow(client.data(), width, j, GL_RGBA, GL_UNSIGNED_BYTE, layout, rgba.data());
      for (int i = 0; i < width; ++i)
        glass::gl::storeTexel(glass::gl::BaseFormat::RGBA, &rgba[static_cast<size_t>(i) * 4],
                              &converted[(static_cast<size_t>(j) * width + i) * 4]);
    }
    CHECK(copied == converted);
    // Every byte value appears in every channel.
    for (int c = 0; c < 4; ++c) {
      std::vector<bool> seen(256, false);
      for (size_t p = 0; p < copied.size() / 4; ++p) seen[copied[p * 4 + c]] = true;
      CHECK(std::count(seen.begin(), seen.end(), true) == 256);
    }
  }
}

// glDrawPixels's fast path takes colours of unsigned bytes as bytes (unpackByteColorSpan) where
// the reference path unpacks each byte b as b / 255 (unpackColorRow) and the fragment stage
// converts it back (floatToColorByte). The bytes must be what that conversion gives: every byte
// value in every colour format, with padding, row length and skips, from a column inside the row.
TEST_CASE("unpack_byte_color_span_matches_floats") {
  using glass::gl::PixelLayout;
  const GLenum formats[] = {GL_RGBA, GL_BGRA, GL_RGB, GL_BGR, GL_RED, GL_GREEN, GL_BLUE,
                            GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA};
  const int width = 262, column = 3, count = 256, row = 1;
  std::vector<uint8_t> client(static_cast<size_t>(300) * 4 * 4 + 64);
  for (size_t i = 0; i < client.size(); ++i) client[i] = static_cast<uint8_t>((i * 7 + i / 4) & 255);
  for (const GLenum format : formats) {
    for (const int alignment : {1, 2, 4, 8}) {
      PixelLayout layout{};
      layout.alignment = alignment;
      layout.rowLength = 300;
      layout.skipPixels = 2;
      layout.skipRows = 1;
      CAPTURE(format);
      CAPTURE(alignment);
      std::vector<uint8_t> bytes(static_cast<size_t>(count) * 4, kUntouched);
      REQUIRE(glass::gl::unpackByteColorSpan(client.data(), count, width, column, row, format,
                                             GL_UNSIGNED_BYTE, layout, bytes.data()));
      std::vector<float> rgba(static_cast<size_t>(width) * 4);
      glass::gl::unpackColorRow(client.data(), width, row, format, GL_UNSIGNED_BYTE, layout, rgba.data());
      std::vector<uint8_t> converted(bytes.size());
      for (size_t i = 0; i < converted.size(); ++i)
        converted[i] = glass::gl::floatToColorByte(rgba[static_cast<size_t>(column) * 4 + i]);
      CHECK(bytes == converted);
    }
  }
  // Every byte value reaches every channel of RGBA.
  std::vector<uint8_t> all(256 * 4), bytes(256 * 4);
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<uint8_t>(i / 4 + 85 * (i % 4));
  PixelLayout layout{};
  std::vector<float> rgba(all.size());
  glass::gl::unpackColorRow(all.data(), 256, 0, GL_RGBA, GL_UNSIGNED_BYTE, layout, rgba.data());
  REQUIRE(glass::gl::unpackByteColorSpan(all.data(), 256, 256, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, layout, bytes.data()));
  for (size_t i = 0; i < all.size(); ++i) CHECK(glass::gl::floatToColorByte(rgba[i]) == all[i]);
  CHECK(bytes == all);
  // Other types are left to the conversion, with nothing written.
  std::vector<uint8_t> untouched(64, kUntouched), buffer = untouched;
  CHECK_FALSE(glass::gl::unpackByteColorSpan(all.data(), 4, 4, 0, 0, GL_RGBA, GL_UNSIGNED_SHORT, layout,
                                             buffer.data()));
  CHECK_FALSE(glass::gl::unpackByteColorSpan(all.data(), 4, 4, 0, 0, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8,
                                             layout, buffer.data()));
  CHECK(buffer == untouched);
}
