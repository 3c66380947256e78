// glass/image.h: image files decoded to RGBA8 rows, bottom row first, and the messages for files
// that cannot be read. The PNG is a small file in tests/unit/data; BMP, TGA and JPEG copies of
// the same pixels are written by the test itself.
#include <doctest/doctest.h>
#include <glass/image.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace {

const std::string kPng = std::string(GLASS_SOURCE_DIR) + "/tests/unit/data/texture_4x3.png";

// The file's pixels, top row first as stored in the file (see tests/unit/data).
const unsigned char kFileRows[3][4][4] = {
    {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}},
    {{10, 20, 30, 255}, {40, 50, 60, 128}, {70, 80, 90, 64}, {100, 110, 120, 0}},
    {{0, 0, 0, 255}, {128, 128, 128, 255}, {255, 255, 0, 255}, {0, 255, 255, 255}}};

const unsigned char* loadedTexel(const glass::Image& image, int column, int rowFromBottom) {
  return &image.rgba[(static_cast<size_t>(rowFromBottom) * image.width + column) * 4];
}

std::string temporaryPath(const char* name) {
  return (std::filesystem::temp_directory_path() / name).string();
}

}  // namespace

TEST_CASE("a PNG loads as RGBA8 with the file's top row as the texture's top row") {
  glass::Image image;
  std::string error;
  REQUIRE(glass::loadImageFile(kPng, image, error));
  CHECK(error.empty());
  CHECK(image.width == 4);
  CHECK(image.height == 3);
  REQUIRE(image.rgba.size() == 4u * 3u * 4u);
  for (int fileRow = 0; fileRow < 3; ++fileRow) {
    for (int column = 0; column < 4; ++column) {
      const unsigned char* t = loadedTexel(image, column, 2 - fileRow);
      for (int c = 0; c < 4; ++c) CHECK(t[c] == kFileRows[fileRow][column][c]);
    }
  }
}

TEST_CASE("BMP, TGA and JPEG load too") {
  const std::string bmp = temporaryPath("glass_texture_test.bmp");
  const std::string tga = temporaryPath("glass_texture_test.tga");
  const std::string jpg = temporaryPath("glass_texture_test.jpg");
  REQUIRE(stbi_write_bmp(bmp.c_str(), 4, 3, 4, kFileRows));
  REQUIRE(stbi_write_tga(tga.c_str(), 4, 3, 4, kFileRows));
  // A flat grey JPEG: lossy compression keeps a uniform colour within a step or two.
  std::vector<unsigned char> grey(8 * 8 * 3, 100);
  REQUIRE(stbi_write_jpg(jpg.c_str(), 8, 8, 3, grey.data(), 95));

  glass::Image image;
  std::string error;
  for (const std::string& path : {bmp, tga}) {
    INFO(path);
    REQUIRE(glass::loadImageFile(path, image, error));
    CHECK(image.width == 4);
    CHECK(image.height == 3);
    // The top-left texel of the file is the first texel of the top row.
    const unsigned char* topLeft = loadedTexel(image, 0, 2);
    CHECK(topLeft[0] == 255);
    CHECK(topLeft[1] == 0);
    CHECK(topLeft[2] == 0);
  }
  REQUIRE(glass::loadImageFile(jpg, image, error));
  CHECK(image.width == 8);
  CHECK(std::abs(static_cast<int>(image.rgba[0]) - 100) <= 2);
  CHECK(image.rgba[3] == 255);  // no alpha in a JPEG: opaque
  std::remove(bmp.c_str());
  std::remove(tga.c_str());
  std::remove(jpg.c_str());
}

TEST_CASE("a file that cannot be read gives a message with its path and the reason") {
  glass::Image image;
  std::string error;
  const std::string missing = temporaryPath("glass_no_such_texture.png");
  CHECK_FALSE(glass::loadImageFile(missing, image, error));
  CHECK(error.find(missing) == 0);
  CHECK(error.find("cannot open") != std::string::npos);
  CHECK(error.find("No such file") != std::string::npos);
  CHECK(image.rgba.empty());

  const std::string garbage = temporaryPath("glass_not_an_image.png");
  {
    std::FILE* f = std::fopen(garbage.c_str(), "wb");
    REQUIRE(f != nullptr);
    std::fputs("this is text, not a picture", f);
    std::fclose(f);
  }
  CHECK_FALSE(glass::loadImageFile(garbage, image, error));
  CHECK(error.find(garbage) == 0);
  CHECK(error.find("not an image in a supported format") != std::string::npos);
  std::remove(garbage.c_str());
}
