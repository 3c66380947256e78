// Mipmap generation (GL_GENERATE_MIPMAP's box filter) and mipmap completeness (spec 3.8.10),
// against averages worked out by hand.
#include <doctest/doctest.h>

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "texture/mipmap_generation.h"
#include "texture/texture_object.h"

using glass::gl::BaseFormat;
using glass::gl::generateMipmaps;
using glass::gl::reduceImageByBoxFilter;
using glass::gl::TextureImage;
using glass::gl::TextureObject;

namespace {

// A luminance image whose texel (i, j) has the value values[j * width + i] in every channel.
TextureImage luminanceImage(int width, int height, std::initializer_list<int> values) {
  TextureImage image;
  image.width = width;
  image.height = height;
  image.internalFormat = GL_LUMINANCE;
  image.base = BaseFormat::Luminance;
  for (int v : values) {
    const auto b = static_cast<uint8_t>(v);
    image.texels.insert(image.texels.end(), {b, b, b, 255});
  }
  REQUIRE(image.texels.size() == static_cast<size_t>(width * height * 4));
  return image;
}

int red(const TextureImage& image, int i, int j) { return image.texel(i, j)[0]; }

}  // namespace

TEST_CASE("halving averages 2 x 2 blocks, rounding halves up") {
  const TextureImage source = luminanceImage(4, 2, {0, 255, 10, 11,    //
                                                    0, 0, 12, 13});
  const TextureImage half = reduceImageByBoxFilter(source);
  CHECK(half.width == 2);
  CHECK(half.height == 1);
  CHECK(red(half, 0, 0) == 64);  // (0 + 255 + 0 + 0) / 4 = 63.75
  CHECK(red(half, 1, 0) == 12);  // (10 + 11 + 12 + 13) / 4 = 11.5, half rounds up
  CHECK(half.texel(0, 0)[3] == 255);
  CHECK(half.base == BaseFormat::Luminance);
  CHECK(half.internalFormat == GL_LUMINANCE);
}

TEST_CASE("a one-texel-high image halves along its width only") {
  const TextureImage source = luminanceImage(4, 1, {100, 200, 7, 8});
  const TextureImage half = reduceImageByBoxFilter(source);
  CHECK(half.width == 2);
  CHECK(half.height == 1);
  CHECK(red(half, 0, 0) == 150);
  CHECK(red(half, 1, 0) == 8);  // 7.5 rounds up
}

TEST_CASE("an odd width shares the middle texel between its two neighbours") {
  // 5 texels to 2: texel 0 covers source [0, 2.5), texel 1 covers [2.5, 5).
  // (2*10 + 2*20 + 1*60) / 5 = 24; (1*60 + 2*40 + 2*50) / 5 = 48.
  const TextureImage source = luminanceImage(5, 1, {10, 20, 60, 40, 50});
  const TextureImage half = reduceImageByBoxFilter(source);
  CHECK(half.width == 2);
  CHECK(red(half, 0, 0) == 24);
  CHECK(red(half, 1, 0) == 48);
}

TEST_CASE("a 3 x 3 image reduces to the mean of all nine texels") {
  const TextureImage source = luminanceImage(3, 3, {9, 9, 9, 9, 90, 9, 9, 9, 9});
  const TextureImage one = reduceImageByBoxFilter(source);
  CHECK(one.width == 1);
  CHECK(one.height == 1);
  CHECK(red(one, 0, 0) == 18);  // (8 * 9 + 90) / 9
}

TEST_CASE("GENERATE_MIPMAP builds the whole chain and makes the texture complete") {
  TextureObject texture;
  texture.target = GL_TEXTURE_2D;
  texture.levels[0] = luminanceImage(8, 2, {0, 0, 0, 0, 255, 255, 255, 255,  //
                                            0, 0, 0, 0, 255, 255, 255, 255});
  texture.updateCompleteness();
  CHECK_FALSE(texture.complete);  // the default minification filter uses mipmaps
  generateMipmaps(texture);
  CHECK(texture.complete);
  CHECK(texture.lastLevel == 3);
  CHECK(texture.levels[1].width == 4);
  CHECK(texture.levels[1].height == 1);
  CHECK(texture.levels[2].width == 2);
  CHECK(texture.levels[3].width == 1);
  CHECK(texture.levels[3].height == 1);
  CHECK(red(texture.levels[1], 0, 0) == 0);
  CHECK(red(texture.levels[1], 3, 0) == 255);
  CHECK(red(texture.levels[2], 0, 0) == 0);
  CHECK(red(texture.levels[2], 1, 0) == 255);
  CHECK(red(texture.levels[3], 0, 0) == 128);  // 127.5 rounds up
}

TEST_CASE("mipmap completeness follows spec 3.8.10") {
  TextureObject texture;
  texture.target = GL_TEXTURE_2D;
  texture.levels[0] = luminanceImage(2, 2, {1, 2, 3, 4});
  texture.params.minFilter = GL_LINEAR;
  texture.updateCompleteness();
  CHECK(texture.complete);  // no mipmaps needed

  texture.params.minFilter = GL_LINEAR_MIPMAP_LINEAR;
  texture.updateCompleteness();
  CHECK_FALSE(texture.complete);  // level 1 is missing

  texture.levels[1] = luminanceImage(1, 1, {5});
  texture.updateCompleteness();
  CHECK(texture.complete);

  texture.levels[1].internalFormat = GL_RGB;  // a different internal format
  texture.updateCompleteness();
  CHECK_FALSE(texture.complete);
  texture.levels[1].internalFormat = GL_LUMINANCE;

  // TEXTURE_MAX_LEVEL 0 needs the base level only.
  texture.levels[1] = TextureImage();
  texture.params.maxLevel = 0;
  texture.updateCompleteness();
  CHECK(texture.complete);

  // A base level above the max level is incomplete.
  texture.params.baseLevel = 1;
  texture.updateCompleteness();
  CHECK_FALSE(texture.complete);
}
