// The image comparison as a module the `glass` program loads only for `glass compare`
// (tools/glass/compare_command.cpp): OpenImageIO and the 260 libraries it needs are then not
// loaded, and their symbols not resolved, every time glass starts (0.2 s on a 2-core machine).
#include <glass/image_compare.h>

#include <iostream>
#include <string>
#include <vector>

// `glass compare`'s arguments after the command's name; prints what runImageCompare prints and
// returns its exit status (2 with a message for arguments it cannot take).
extern "C" __attribute__((visibility("default"))) int glassCompareRun(int argc, const char *const *argv) {
  const std::vector<std::string> args(argv, argv + argc);
  std::string error;
  const std::optional<glass::ImageCompareRequest> request = glass::parseImageCompareArguments(args, error);
  if (!request) {
    std::cerr << "glass compare: " << error << "\n(see glass compare --help)\n";
    return 2;
  }
  return glass::runImageCompare(*request, std::cout, std::cerr);
}
