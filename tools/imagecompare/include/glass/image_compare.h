// Image comparison: how far a rendered picture is from a reference, in numbers.
//
// Used by the image tests (tests/image) and by `glass compare A.png B.png [--fail-psnr DB]
// [--fail-percent P] [--diff D.png]`. The measures come from OpenImageIO's
// ImageBufAlgo::compare over the red, green and blue channels (alpha is not part of the
// picture a person sees), with channel values scaled to [0, 1]:
//   PSNR          20 log10(1 / RMS error) in dB; +infinity when the images are identical;
//   mean error    mean absolute channel difference;
//   max error     largest absolute channel difference, and the pixel where it occurs;
//   pixels off    pixels with some channel off by more than 8/255, and their share in percent.
#pragma once

#include <iosfwd>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace glass {

struct ImageDifference {
  int width = 0;
  int height = 0;
  int channels = 0;  // channels compared: 3 (RGB) unless an image has fewer
  double psnr = std::numeric_limits<double>::infinity();
  double meanError = 0.0;
  double maxError = 0.0;
  int maxErrorX = 0;  // column and row of the largest difference, row 0 at the top
  int maxErrorY = 0;
  long long pixelsOff = 0;
  double percentOff = 0.0;

  bool identical() const { return maxError == 0.0; }
};

// A pixel is "off" when one of its channels differs by more than this. Channels of 8-bit images
// are multiples of 1/255, so any threshold in (8/255, 9/255) counts exactly the differences of
// 9 or more steps; the midpoint keeps float rounding of the difference away from the boundary.
inline constexpr double kPixelOffThreshold = 8.5 / 255.0;

// Limits beyond which a comparison fails. An unset limit is not checked.
struct ImageCompareLimits {
  std::optional<double> failPsnr;     // fail when PSNR is below this (dB); +inf: must be identical
  std::optional<double> failPercent;  // fail when more than this percent of pixels are off
};

// Reads both images and measures their difference. Returns nothing and sets `error` when a file
// cannot be read or the sizes differ.
std::optional<ImageDifference> compareImageFiles(const std::string& pathA, const std::string& pathB,
                                                 std::string& error);

// True when `difference` breaks one of `limits`; `reasons` (if given) gets one line per broken limit.
bool exceedsLimits(const ImageDifference& difference, const ImageCompareLimits& limits,
                   std::vector<std::string>* reasons = nullptr);

// Writes a picture of where A and B differ: pixels off by more than 8/255 in red, smaller
// differences in yellow, equal pixels as a dimmed grey copy of A. Written whole or not at all.
bool writeDiffImage(const std::string& pathA, const std::string& pathB, const std::string& diffPath,
                    std::string& error);

// One line per measure, for people: sizes, PSNR, mean and max error, pixels off.
void printImageDifference(std::ostream& out, const ImageDifference& difference);

// The `glass compare` command.
struct ImageCompareRequest {
  std::string pathA;
  std::string pathB;
  ImageCompareLimits limits;
  std::string diffPath;          // empty: no diff image
  bool diffOnlyOnFailure = false;  // false: write the diff image whenever diffPath is set
};

// Parses `A.png B.png [--fail-psnr DB] [--fail-percent P] [--diff D.png]` (the arguments after
// the command name). Returns nothing and sets `error` on a bad command line.
std::optional<ImageCompareRequest> parseImageCompareArguments(const std::vector<std::string>& args,
                                                              std::string& error);

// Compares, prints the measures to `out`, writes the diff image if asked. Returns the exit status:
// 0 within the limits, 1 beyond them, 2 when the images cannot be compared (message on `err`).
int runImageCompare(const ImageCompareRequest& request, std::ostream& out, std::ostream& err);

}  // namespace glass
