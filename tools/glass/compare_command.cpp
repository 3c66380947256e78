// `glass compare`: how far one picture is from another, through the image comparison library
// (tools/imagecompare, OpenImageIO).
#include "command_registry.h"

#include <glass/image_compare.h>

#include <iostream>

namespace glass::cli {

namespace {

constexpr const char *kHelp = R"(usage: glass compare A B [--fail-psnr DB] [--fail-percent P] [--diff D.png]

Compares two pictures of the same size over their red, green and blue channels and prints
the PSNR, the mean and the largest channel error, and how many pixels are off by more than
8/255 (and their share).

options:
  --fail-psnr DB        fail (exit 1) when the PSNR is below DB decibels ("inf": must be equal)
  --fail-percent P      fail (exit 1) when more than P percent of the pixels are off
  --diff D.png          write a picture of the differences: pixels off by more than 8/255 in
                        red, smaller differences in yellow, equal pixels in dimmed grey
  -h, --help            this help

exit status: 0 within the limits, 1 beyond them, 2 bad usage or pictures that cannot be
compared (unreadable, or of different sizes)

examples:
  glass compare out/showcase.png reference_images/scenes/showcase.png
  glass compare glass.png mesa.png --fail-psnr 40 --fail-percent 0.5 --diff diff.png
)";

int runCompare(const std::vector<std::string> &args) {
  if (wantsHelp(args)) {
    std::cout << kHelp;
    return kExitOk;
  }
  std::string error;
  std::optional<ImageCompareRequest> request = parseImageCompareArguments(args, error);
  if (!request) {
    std::cerr << "glass compare: " << error << "\n(see glass compare --help)\n";
    return kExitUsage;
  }
  return runImageCompare(*request, std::cout, std::cerr);
}

const bool registered = registerCommand({"compare", "measure how far one picture is from another (PSNR, pixels off)", runCompare});

} // namespace

} // namespace glass::cli
