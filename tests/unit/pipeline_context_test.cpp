// glass/context.h: creating contexts, making them current per thread, reading the colour buffer
// and writing PNG files whole or not at all.
#include <GL/gl.h>
#include <doctest/doctest.h>
#include <glass/context.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include <unistd.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "pipeline_test_support.h"

namespace fs = std::filesystem;

TEST_CASE("pipeline context: sizes, current context and the colour buffer") {
  CHECK(glassCreateContext(0, 10) == nullptr);
  CHECK(glassCreateContext(10, -1) == nullptr);
  CHECK(glassCreateContext(16385, 10) == nullptr);
  glassDestroyContext(nullptr);  // harmless

  GlassContext* ctx = glassCreateContext(3, 2);
  REQUIRE(ctx != nullptr);
  CHECK(glassGetWidth(ctx) == 3);
  CHECK(glassGetHeight(ctx) == 2);
  CHECK(glassMakeCurrent(ctx) == 1);
  CHECK(glassGetCurrentContext() == ctx);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const unsigned char* pixels = glassGetColorBuffer(ctx);
  REQUIRE(pixels != nullptr);
  CHECK((pixels[0] == 255 && pixels[1] == 0 && pixels[3] == 255));
  CHECK(pixels[5 * 4] == 255);  // the last pixel
  glassDestroyContext(ctx);
  CHECK(glassGetCurrentContext() == nullptr);  // destroying the current context releases it
  CHECK(glassGetWidth(nullptr) == 0);
  CHECK(glassGetColorBuffer(nullptr) == nullptr);
}

TEST_CASE("pipeline context: the current context is per thread") {
  GlassContext* mine = glassCreateContext(4, 4);
  GlassContext* theirs = glassCreateContext(4, 4);
  glassMakeCurrent(mine);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  std::thread other([theirs] {
    // Nothing is current on a new thread: GL calls do nothing.
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glassMakeCurrent(theirs);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glassMakeCurrent(nullptr);
  });
  other.join();

  CHECK(glassGetCurrentContext() == mine);
  CHECK(glass::test::pixelAt(1, 1) == glass::test::Rgba{0, 0, 255, 255});
  CHECK(glassGetColorBuffer(theirs)[0] == 255);
  glassDestroyContext(theirs);
  glassDestroyContext(mine);
}

TEST_CASE("pipeline context: glassWritePNG writes the picture top row first, whole or not at all") {
  const fs::path dir = fs::temp_directory_path() / ("glass_png_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "picture.png";

  GlassContext* ctx = glassCreateContext(5, 4);
  glassMakeCurrent(ctx);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glass::test::pixelProjection(5, 4);
  glColor3ub(10, 20, 30);
  glRecti(0, 0, 5, 1);  // the bottom row

  REQUIRE(glassWritePNG(ctx, file.c_str()) == 1);
  int width = 0, height = 0, channels = 0;
  unsigned char* image = stbi_load(file.c_str(), &width, &height, &channels, 0);
  REQUIRE(image != nullptr);
  CHECK(width == 5);
  CHECK(height == 4);
  CHECK(channels == 3);
  const unsigned char* bottom = image + (height - 1) * width * channels;
  CHECK((bottom[0] == 10 && bottom[1] == 20 && bottom[2] == 30));
  CHECK((image[0] == 0 && image[1] == 0 && image[2] == 0));
  stbi_image_free(image);

  // A path that cannot be written: failure, and nothing left behind.
  const fs::path missing = dir / "no_such_directory" / "picture.png";
  CHECK(glassWritePNG(ctx, missing.c_str()) == 0);
  CHECK(glassWritePNG(nullptr, file.c_str()) == 0);
  CHECK(glassWritePNG(ctx, nullptr) == 0);
  int entries = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    (void)entry;
    ++entries;
  }
  CHECK(entries == 1);  // only picture.png: no temporary file remains

  glassDestroyContext(ctx);
  fs::remove_all(dir);
}
