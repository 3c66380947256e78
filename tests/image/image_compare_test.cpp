// Tests of the image comparison library (glass/image_compare.h) on small synthetic pictures.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "glass/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kDirectory = std::filesystem::path(GLASS_TEST_OUTPUT_DIR);

// Writes a width x height RGB PNG of one grey level, with the listed pixels changed by `delta`
// in the green channel; returns its path.
std::string writePicture(const std::string& name, int width, int height, int grey,
                         const std::vector<std::pair<int, int>>& changed = {}, int delta = 0) {
  std::vector<unsigned char> pixels(size_t(width) * height * 3, (unsigned char)grey);
  for (auto [x, y] : changed)
    pixels[(size_t(y) * width + x) * 3 + 1] = (unsigned char)(grey + delta);
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8), pixels.data());
  const std::string path = (kDirectory / name).string();
  REQUIRE(image.write(path));
  return path;
}

glass::ImageDifference compare(const std::string& a, const std::string& b) {
  std::string error;
  const std::optional<glass::ImageDifference> difference = glass::compareImageFiles(a, b, error);
  REQUIRE_MESSAGE(difference, error);
  return *difference;
}

}  // namespace

TEST_CASE("identical pictures: infinite PSNR, nothing off, within any limits") {
  const std::string a = writePicture("same_a.png", 16, 8, 100);
  const std::string b = writePicture("same_b.png", 16, 8, 100);
  const glass::ImageDifference d = compare(a, b);
  CHECK(d.width == 16);
  CHECK(d.height == 8);
  CHECK(d.channels == 3);
  CHECK(std::isinf(d.psnr));
  CHECK(d.identical());
  CHECK(d.pixelsOff == 0);
  CHECK_FALSE(glass::exceedsLimits(d, {std::numeric_limits<double>::infinity(), 0.0}));
}

TEST_CASE("a pixel is off only beyond 8/255") {
  const std::string reference = writePicture("grey.png", 10, 10, 100);
  const std::vector<std::pair<int, int>> four = {{0, 0}, {3, 4}, {9, 9}, {5, 0}};

  const glass::ImageDifference by8 =
      compare(writePicture("by8.png", 10, 10, 100, four, 8), reference);
  CHECK(by8.pixelsOff == 0);
  CHECK(by8.maxError == doctest::Approx(8.0 / 255.0));
  CHECK_FALSE(by8.identical());

  const glass::ImageDifference by9 =
      compare(writePicture("by9.png", 10, 10, 100, four, 9), reference);
  CHECK(by9.pixelsOff == 4);
  CHECK(by9.percentOff == doctest::Approx(4.0));
  // One channel of four pixels off by 9/255: MSE = 4 (9/255)^2 / 300.
  CHECK(by9.psnr == doctest::Approx(-10.0 * std::log10(4.0 * std::pow(9.0 / 255.0, 2) / 300.0)));
  CHECK(by9.meanError == doctest::Approx(4.0 * 9.0 / 255.0 / 300.0));
}

TEST_CASE("limits: PSNR floor, share of pixels off, and inf for identical") {
  glass::ImageDifference d;
  d.psnr = 35.0;
  d.percentOff = 0.2;
  std::vector<std::string> reasons;
  CHECK_FALSE(glass::exceedsLimits(d, {30.0, 0.5}));
  CHECK(glass::exceedsLimits(d, {40.0, 0.5}, &reasons));
  CHECK(reasons.size() == 1);
  CHECK(glass::exceedsLimits(d, {30.0, 0.1}));
  CHECK(glass::exceedsLimits(d, {std::numeric_limits<double>::infinity(), std::nullopt}));
  CHECK_FALSE(glass::exceedsLimits(d, {}));
}

TEST_CASE("pictures of different sizes cannot be compared") {
  std::string error;
  CHECK_FALSE(glass::compareImageFiles(writePicture("small.png", 4, 4, 0),
                                       writePicture("large.png", 5, 4, 0), error));
  CHECK(error.find("sizes differ") != std::string::npos);
  CHECK_FALSE(glass::compareImageFiles((kDirectory / "missing.png").string(),
                                       writePicture("any.png", 4, 4, 0), error));
}

TEST_CASE("the diff picture marks pixels off in red and smaller differences in yellow") {
  const std::string reference = writePicture("base.png", 6, 2, 40);
  const std::string changed = writePicture("changed.png", 6, 2, 40, {{1, 0}}, 30);
  const std::string slightly = writePicture("slightly.png", 6, 2, 40, {{1, 0}}, 3);
  const std::string diffPath = (kDirectory / "changed.diff.png").string();
  const std::string slightPath = (kDirectory / "slightly.diff.png").string();
  std::string error;
  REQUIRE(glass::writeDiffImage(changed, reference, diffPath, error));
  OIIO::ImageBuf diff(diffPath);
  float rgb[3];
  diff.getpixel(1, 0, rgb, 3);
  CHECK(rgb[0] == 1.0f);
  CHECK(rgb[1] == 0.0f);
  diff.getpixel(0, 0, rgb, 3);
  CHECK(rgb[0] == doctest::Approx(10.0 / 255.0));  // a quarter of the grey level 40

  REQUIRE(glass::writeDiffImage(slightly, reference, slightPath, error));
  OIIO::ImageBuf yellow(slightPath);
  yellow.getpixel(1, 0, rgb, 3);
  CHECK(rgb[0] == 1.0f);
  CHECK(rgb[1] > 0.5f);
}

TEST_CASE("glass compare: arguments, report and exit status") {
  std::string error;
  CHECK_FALSE(glass::parseImageCompareArguments({"a.png"}, error));
  CHECK_FALSE(glass::parseImageCompareArguments({"a.png", "b.png", "--fail-psnr"}, error));
  CHECK_FALSE(glass::parseImageCompareArguments({"a.png", "b.png", "--fail-psnr", "x"}, error));
  CHECK_FALSE(glass::parseImageCompareArguments({"a.png", "b.png", "--bogus"}, error));
  const auto request = glass::parseImageCompareArguments(
      {"a.png", "--fail-psnr", "inf", "b.png", "--fail-percent", "0.5", "--diff", "d.png"}, error);
  REQUIRE(request);
  CHECK(request->pathA == "a.png");
  CHECK(request->pathB == "b.png");
  CHECK(std::isinf(*request->limits.failPsnr));
  CHECK(*request->limits.failPercent == 0.5);
  CHECK(request->diffPath == "d.png");

  const std::string a = writePicture("run_a.png", 8, 8, 90);
  const std::string b = writePicture("run_b.png", 8, 8, 90, {{2, 2}}, 50);
  std::ostringstream out, err;
  glass::ImageCompareRequest same{a, a, {std::numeric_limits<double>::infinity(), 0.0}, "", false};
  CHECK(glass::runImageCompare(same, out, err) == 0);
  glass::ImageCompareRequest differ{
      a, b, {std::numeric_limits<double>::infinity(), 0.0}, "", false};
  CHECK(glass::runImageCompare(differ, out, err) == 1);
  CHECK(out.str().find("FAIL") != std::string::npos);
  glass::ImageCompareRequest missing{a, (kDirectory / "none.png").string(), {}, "", false};
  CHECK(glass::runImageCompare(missing, out, err) == 2);
}
