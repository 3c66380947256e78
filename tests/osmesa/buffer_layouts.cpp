// Every format and type pair, OSMESA_Y_UP both ways, OSMESA_ROW_LENGTH padding: the caller's
// buffer holds the RGBA picture converted as <GL/osmesa.h> describes, and nothing outside it.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "osmesa_test_scene.h"

using osmesa_test::createContext;
using osmesa_test::drawScene;
using osmesa_test::renderRGBA;

namespace {

constexpr int kWidth = 83, kHeight = 67;  // not multiples of the 64-pixel tiles
constexpr uint8_t kSentinel = 0xA5;

struct Pair {
  GLenum format;
  GLenum type;
  const char* name;
  int components;  // 0 for 565
  int order[4];    // the RGBA component at each position
};

const Pair kPairs[] = {
    {OSMESA_RGBA, GL_UNSIGNED_BYTE, "RGBA/UNSIGNED_BYTE", 4, {0, 1, 2, 3}},
    {OSMESA_RGBA, GL_UNSIGNED_SHORT, "RGBA/UNSIGNED_SHORT", 4, {0, 1, 2, 3}},
    {OSMESA_RGBA, GL_FLOAT, "RGBA/FLOAT", 4, {0, 1, 2, 3}},
    {OSMESA_BGRA, GL_UNSIGNED_BYTE, "BGRA/UNSIGNED_BYTE", 4, {2, 1, 0, 3}},
    {OSMESA_BGRA, GL_UNSIGNED_SHORT, "BGRA/UNSIGNED_SHORT", 4, {2, 1, 0, 3}},
    {OSMESA_BGRA, GL_FLOAT, "BGRA/FLOAT", 4, {2, 1, 0, 3}},
    {OSMESA_ARGB, GL_UNSIGNED_BYTE, "ARGB/UNSIGNED_BYTE", 4, {3, 0, 1, 2}},
    {OSMESA_ARGB, GL_UNSIGNED_SHORT, "ARGB/UNSIGNED_SHORT", 4, {3, 0, 1, 2}},
    {OSMESA_ARGB, GL_FLOAT, "ARGB/FLOAT", 4, {3, 0, 1, 2}},
    {OSMESA_RGB, GL_UNSIGNED_BYTE, "RGB/UNSIGNED_BYTE", 3, {0, 1, 2, 0}},
    {OSMESA_RGB, GL_UNSIGNED_SHORT, "RGB/UNSIGNED_SHORT", 3, {0, 1, 2, 0}},
    {OSMESA_RGB, GL_FLOAT, "RGB/FLOAT", 3, {0, 1, 2, 0}},
    {OSMESA_BGR, GL_UNSIGNED_BYTE, "BGR/UNSIGNED_BYTE", 3, {2, 1, 0, 0}},
    {OSMESA_BGR, GL_UNSIGNED_SHORT, "BGR/UNSIGNED_SHORT", 3, {2, 1, 0, 0}},
    {OSMESA_BGR, GL_FLOAT, "BGR/FLOAT", 3, {2, 1, 0, 0}},
    {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, "RGB_565/UNSIGNED_SHORT_5_6_5", 0, {0, 0, 0, 0}},
};

size_t pixelBytes(const Pair& pair) {
  if (pair.components == 0) return 2;
  const size_t size = pair.type == GL_UNSIGNED_BYTE ? 1 : pair.type == GL_UNSIGNED_SHORT ? 2 : 4;
  return size * static_cast<size_t>(pair.components);
}

// The bytes one RGBA8 pixel becomes: c, c * 257, c / 255, or 5-6-5 rounded to nearest.
std::vector<uint8_t> expectedPixel(const Pair& pair, const uint8_t* rgba) {
  std::vector<uint8_t> bytes(pixelBytes(pair));
  if (pair.components == 0) {
    const uint16_t packed = static_cast<uint16_t>(((rgba[0] * 31 + 127) / 255) << 11 |
                                                  ((rgba[1] * 63 + 127) / 255) << 5 |
                                                  ((rgba[2] * 31 + 127) / 255));
    std::memcpy(bytes.data(), &packed, 2);
    return bytes;
  }
  for (int i = 0; i < pair.components; ++i) {
    const uint8_t c = rgba[pair.order[i]];
    if (pair.type == GL_UNSIGNED_BYTE) {
      bytes[static_cast<size_t>(i)] = c;
    } else if (pair.type == GL_UNSIGNED_SHORT) {
      const uint16_t v = static_cast<uint16_t>(c * 257);
      std::memcpy(&bytes[static_cast<size_t>(i) * 2], &v, 2);
    } else {
      const float v = static_cast<float>(c) / 255.0f;
      std::memcpy(&bytes[static_cast<size_t>(i) * 4], &v, 4);
    }
  }
  return bytes;
}

// Checks the buffer against the RGBA picture: each pixel converted, rows in the order yUp says,
// and the padding of every row (rowLength > width) untouched.
void checkBuffer(const Pair& pair, const std::vector<uint8_t>& buffer, const std::vector<uint8_t>& rgba,
                 int rowLength, bool yUp) {
  const size_t bpp = pixelBytes(pair);
  int wrongPixels = 0, touchedPadding = 0;
  for (int row = 0; row < kHeight; ++row) {
    const int bufferRow = yUp ? row : kHeight - 1 - row;
    const uint8_t* line = &buffer[static_cast<size_t>(bufferRow) * rowLength * bpp];
    for (int x = 0; x < kWidth; ++x) {
      const auto expected = expectedPixel(pair, &rgba[(static_cast<size_t>(row) * kWidth + x) * 4]);
      if (std::memcmp(line + x * bpp, expected.data(), bpp) != 0) ++wrongPixels;
    }
    for (size_t i = kWidth * bpp; i < rowLength * bpp; ++i) {
      if (line[i] != kSentinel) ++touchedPadding;
    }
  }
  CHECK(wrongPixels == 0);
  CHECK(touchedPadding == 0);
}

}  // namespace

TEST_CASE("every format and type pair, both row orders, with and without row padding") {
  const std::vector<uint8_t> rgba = renderRGBA(kWidth, kHeight, 3);
  // The picture is not empty: several colours.
  CHECK(std::memcmp(&rgba[0], &rgba[(kWidth * kHeight / 2 + kWidth / 2) * 4], 3) != 0);
  for (const Pair& pair : kPairs) {
    for (int rowLength : {0, kWidth + 5}) {
      for (bool yUp : {true, false}) {
        CAPTURE(pair.name);
        CAPTURE(rowLength);
        CAPTURE(yUp);
        const int stride = rowLength ? rowLength : kWidth;
        std::vector<uint8_t> buffer(static_cast<size_t>(stride) * kHeight * pixelBytes(pair),
                                    kSentinel);
        OSMesaContext ctx = createContext(pair.format);
        REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), pair.type, kWidth, kHeight));
        OSMesaPixelStore(OSMESA_ROW_LENGTH, rowLength);
        OSMesaPixelStore(OSMESA_Y_UP, yUp ? 1 : 0);
        GLint value = -1;
        OSMesaGetIntegerv(OSMESA_TYPE, &value);
        CHECK(value == static_cast<GLint>(pair.type));
        OSMesaGetIntegerv(OSMESA_FORMAT, &value);
        CHECK(value == static_cast<GLint>(pair.format));
        OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &value);
        CHECK(value == rowLength);
        OSMesaGetIntegerv(OSMESA_Y_UP, &value);
        CHECK(value == (yUp ? 1 : 0));
        // Row padding is never written, so the sentinel survives OSMesaPixelStore's store.
        drawScene(3);
        CHECK(glGetError() == GL_NO_ERROR);
        checkBuffer(pair, buffer, rgba, stride, yUp);
        OSMesaDestroyContext(ctx);
      }
    }
  }
}

TEST_CASE("a format does not take the other types, and a refused binding changes nothing") {
  const GLenum types[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT, GL_UNSIGNED_SHORT_5_6_5,
                          GL_BYTE, GL_INT, GL_UNSIGNED_INT};
  const GLenum formats[] = {OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR,
                            OSMESA_RGB_565};
  std::vector<uint8_t> current(16 * 16 * 4, 0);
  OSMesaContext bound = createContext(OSMESA_RGBA);
  REQUIRE(OSMesaMakeCurrent(bound, current.data(), GL_UNSIGNED_BYTE, 16, 16));
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (GLenum format : formats) {
    OSMesaContext ctx = createContext(format);
    for (GLenum type : types) {
      bool accepted = false;
      for (const Pair& pair : kPairs) accepted |= pair.format == format && pair.type == type;
      if (accepted) continue;
      CAPTURE(format);
      CAPTURE(type);
      std::vector<uint8_t> buffer(16 * 16 * 16, kSentinel);
      CHECK(OSMesaMakeCurrent(ctx, buffer.data(), type, 16, 16) == GL_FALSE);
      CHECK(OSMesaGetCurrentContext() == bound);
      CHECK(buffer == std::vector<uint8_t>(16 * 16 * 16, kSentinel));
    }
    OSMesaDestroyContext(ctx);
  }
  // Sizes, buffers and contexts that are no good.
  std::vector<uint8_t> buffer(64, kSentinel);
  GLint maxWidth = 0, maxHeight = 0;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxWidth);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxHeight);
  CHECK(maxWidth == 16384);
  CHECK(maxHeight == 16384);
  OSMesaContext other = createContext(OSMESA_RGBA);
  CHECK(!OSMesaMakeCurrent(other, buffer.data(), GL_UNSIGNED_BYTE, 0, 4));
  CHECK(!OSMesaMakeCurrent(other, buffer.data(), GL_UNSIGNED_BYTE, 4, -1));
  CHECK(!OSMesaMakeCurrent(other, buffer.data(), GL_UNSIGNED_BYTE, maxWidth + 1, 1));
  CHECK(!OSMesaMakeCurrent(other, buffer.data(), GL_UNSIGNED_BYTE, 1, maxHeight + 1));
  CHECK(!OSMesaMakeCurrent(other, nullptr, GL_UNSIGNED_BYTE, 4, 4));
  CHECK(!OSMesaMakeCurrent(nullptr, buffer.data(), GL_UNSIGNED_BYTE, 4, 4));
  CHECK(OSMesaGetCurrentContext() == bound);
  CHECK(buffer == std::vector<uint8_t>(64, kSentinel));
  GLint width = 0;
  OSMesaGetIntegerv(OSMESA_WIDTH, &width);
  CHECK(width == 16);
  // The bound context still draws into its buffer.
  glFinish();
  CHECK(current[0] == 255);
  CHECK(current[1] == 0);
  OSMesaDestroyContext(other);
  OSMesaDestroyContext(bound);
  CHECK(OSMesaGetCurrentContext() == nullptr);
}

TEST_CASE("OSMesaPixelStore: bad names and values are GL errors and change nothing") {
  std::vector<uint8_t> buffer(20 * 10 * 4, 0);
  OSMesaContext ctx = createContext(OSMESA_RGBA);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 20, 10));
  OSMesaPixelStore(OSMESA_ROW_LENGTH, -1);
  CHECK(glGetError() == GL_INVALID_VALUE);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 19);  // rows would overlap
  CHECK(glGetError() == GL_INVALID_VALUE);
  OSMesaPixelStore(OSMESA_WIDTH, 1);
  CHECK(glGetError() == GL_INVALID_ENUM);
  GLint value = -1;
  OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &value);
  CHECK(value == 0);
  OSMesaGetIntegerv(0x9999, &value);
  CHECK(glGetError() == GL_INVALID_ENUM);
  OSMesaDestroyContext(ctx);
  // Without a current context nothing happens.
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  value = -1;
  OSMesaGetIntegerv(OSMESA_WIDTH, &value);
  CHECK(value == 0);
}

TEST_CASE("the buffer is the colour buffer: its pixels are kept where nothing is drawn") {
  std::vector<uint8_t> buffer(32 * 32 * 4);
  for (size_t i = 0; i < buffer.size(); ++i) buffer[i] = static_cast<uint8_t>(i * 7);
  const std::vector<uint8_t> before = buffer;
  OSMesaContext ctx = createContext(OSMESA_RGBA);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 32, 32));
  glScissor(0, 0, 16, 32);
  glEnable(GL_SCISSOR_TEST);
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const uint8_t* p = &buffer[(static_cast<size_t>(y) * 32 + x) * 4];
      if (x < 16) {
        CHECK(p[1] == 255);
      } else {
        CHECK(std::memcmp(p, &before[(static_cast<size_t>(y) * 32 + x) * 4], 4) == 0);
      }
    }
  }
  OSMesaDestroyContext(ctx);
}
