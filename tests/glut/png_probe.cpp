// Checks a PNG written by a GLUT test: its size, the colour of pixels, how many pixels have a
// colour, or whether it equals another PNG. Pixel coordinates count from the top-left corner, as
// GLUT's mouse coordinates do.
//   png_probe FILE [size W H] [pixel X Y R G B] [count R G B MIN MAX] [same OTHER] [differ OTHER]
//             [darker OTHER]
// Prints each failed check and exits 1 when one fails, 2 on bad usage or an unreadable file.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace {

struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

bool load(const char* path, Picture& picture) {
  int channels = 0;
  unsigned char* data = stbi_load(path, &picture.width, &picture.height, &channels, 3);
  if (!data) {
    std::fprintf(stderr, "png_probe: cannot read %s: %s\n", path, stbi_failure_reason());
    return false;
  }
  picture.rgb.assign(data, data + static_cast<size_t>(picture.width) * picture.height * 3);
  stbi_image_free(data);
  return true;
}

int number(char** argv, int i) { return std::atoi(argv[i]); }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: png_probe FILE [size W H] [pixel X Y R G B] [count R G B MIN MAX] "
                         "[same OTHER] [differ OTHER] [darker OTHER]\n");
    return 2;
  }
  Picture picture;
  if (!load(argv[1], picture)) return 2;
  int failures = 0;
  for (int i = 2; i < argc;) {
    const std::string check = argv[i];
    auto need = [&](int count) {
      if (i + count >= argc) {
        std::fprintf(stderr, "png_probe: '%s' needs %d arguments\n", check.c_str(), count);
        std::exit(2);
      }
    };
    if (check == "size") {
      need(2);
      const int w = number(argv, i + 1), h = number(argv, i + 2);
      if (picture.width != w || picture.height != h) {
        std::printf("%s: size %d x %d, expected %d x %d\n", argv[1], picture.width, picture.height, w, h);
        ++failures;
      }
      i += 3;
    } else if (check == "pixel") {
      need(5);
      const int x = number(argv, i + 1), y = number(argv, i + 2);
      const int r = number(argv, i + 3), g = number(argv, i + 4), b = number(argv, i + 5);
      if (x < 0 || y < 0 || x >= picture.width || y >= picture.height) {
        std::printf("%s: pixel %d,%d is outside the picture\n", argv[1], x, y);
        ++failures;
      } else if (const unsigned char* p = picture.at(x, y); p[0] != r || p[1] != g || p[2] != b) {
        std::printf("%s: pixel %d,%d is %d %d %d, expected %d %d %d\n", argv[1], x, y, p[0], p[1],
                    p[2], r, g, b);
        ++failures;
      }
      i += 6;
    } else if (check == "count") {
      need(5);
      const int r = number(argv, i + 1), g = number(argv, i + 2), b = number(argv, i + 3);
      const long minimum = number(argv, i + 4), maximum = number(argv, i + 5);
      long count = 0;
      for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
          const unsigned char* p = picture.at(x, y);
          count += p[0] == r && p[1] == g && p[2] == b;
        }
      }
      if (count < minimum || count > maximum) {
        std::printf("%s: %ld pixels are %d %d %d, expected %ld to %ld\n", argv[1], count, r, g, b,
                    minimum, maximum);
        ++failures;
      }
      i += 6;
    } else if (check == "darker") {
      // The mean of R + G + B over the picture is below OTHER's by more than 1 % of OTHER's.
      need(1);
      Picture other;
      if (!load(argv[i + 1], other)) return 2;
      auto mean = [](const Picture& p) {
        double sum = 0;
        for (unsigned char c : p.rgb) sum += c;
        return p.rgb.empty() ? 0.0 : sum / static_cast<double>(p.rgb.size());
      };
      const double mine = mean(picture), theirs = mean(other);
      if (!(mine < theirs * 0.99)) {
        std::printf("%s is not darker than %s (mean %.2f against %.2f)\n", argv[1], argv[i + 1], mine,
                    theirs);
        ++failures;
      }
      i += 2;
    } else if (check == "same" || check == "differ") {
      need(1);
      Picture other;
      if (!load(argv[i + 1], other)) return 2;
      const bool same = other.width == picture.width && other.height == picture.height &&
                        other.rgb == picture.rgb;
      if (same != (check == "same")) {
        std::printf("%s and %s are %s\n", argv[1], argv[i + 1], same ? "the same" : "different");
        ++failures;
      }
      i += 2;
    } else {
      std::fprintf(stderr, "png_probe: unknown check '%s'\n", check.c_str());
      return 2;
    }
  }
  return failures ? 1 : 0;
}
