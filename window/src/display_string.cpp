// glutInitDisplayString (GLUT 3.7 spec 2.5): the initial display mode described by words, each a
// capability with an optional comparison and number ("rgb double depth>=16 samples~4"), read
// into the same display mode bits as glutInitDisplayMode.
//
// glass has one framebuffer configuration (RGBA8 with alpha, 24-bit depth, 8-bit stencil, 16-bit
// accumulation, no colour index, stereo or multisampling), so the numbers choose nothing: a
// capability that names a buffer glass has asks for it, and only those it cannot have make
// glutCreateWindow fail as with glutInitDisplayMode ("index", "stereo", and "samples" compared
// so that no samples would not do; "samples" alone means "<= 4" in the specification, which a
// configuration without multisampling meets). Words GLUT does not know get freeglut's warning.
#include <GL/freeglut.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "glut_errors.h"
#include "glut_state.h"

namespace glass::glut {
namespace {

// The capabilities of the specification, and the display mode bit each asks for (0: none).
struct Capability {
  std::string_view name;
  unsigned mode;
};
constexpr Capability kCapabilities[] = {
    {"alpha", GLUT_ALPHA},     {"acca", GLUT_ACCUM},      {"acc", GLUT_ACCUM},
    {"blue", 0},               {"buffer", 0},             {"conformant", 0},
    {"depth", GLUT_DEPTH},     {"double", GLUT_DOUBLE},   {"green", 0},
    {"index", GLUT_INDEX},     {"num", 0},                {"red", 0},
    {"rgba", GLUT_RGBA},       {"rgb", GLUT_RGB},         {"luminance", GLUT_LUMINANCE},
    {"stencil", GLUT_STENCIL}, {"single", GLUT_SINGLE},   {"stereo", GLUT_STEREO},
    {"samples", 0},            {"slow", 0},               {"win32pfd", 0},
    {"xvisual", 0},            {"xstaticgray", 0},        {"xgrayscale", 0},
    {"xstaticcolor", 0},       {"xpseudocolor", 0},       {"xtruecolor", 0},
    {"xdirectcolor", 0},
};

// Whether a configuration without multisampling (0 samples) meets "samples" with this
// comparison and number; with no comparison the specification's default, "<=".
bool zeroSamplesWill(std::string_view comparison, long value) {
  if (comparison.empty() || comparison == "<=") return true;
  if (comparison == "=") return value == 0;
  if (comparison == "!=") return value != 0;
  if (comparison == "<") return value > 0;
  if (comparison == ">=" || comparison == "~") return value <= 0;  // "~": at least, fewest
  return false;  // ">"
}

unsigned displayModeOfString(const char* text) {
  unsigned mode = 0;
  const std::string words = text ? text : "";
  std::size_t at = 0;
  while (at < words.size()) {
    if (words[at] == ' ' || words[at] == '\t') {
      ++at;
      continue;
    }
    const std::size_t end = words.find_first_of(" \t", at);
    const std::string word = words.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos ? words.size() : end;
    const std::size_t nameLength = word.find_first_of("=<>~!");
    const std::string_view name = std::string_view(word).substr(0, nameLength);
    const Capability* found = nullptr;
    for (const Capability& capability : kCapabilities) {
      if (capability.name == name) found = &capability;
    }
    if (!found) {
      warning("Display string token not recognized:  %s", word.c_str());
      continue;
    }
    mode |= found->mode;
    if (name == "samples") {
      std::string_view rest = nameLength == std::string::npos ? std::string_view() : std::string_view(word).substr(nameLength);
      std::size_t comparisonLength = 0;
      while (comparisonLength < rest.size() && std::strchr("=<>~!", rest[comparisonLength])) ++comparisonLength;
      const std::string_view comparison = rest.substr(0, comparisonLength);
      const long value = std::strtol(std::string(rest.substr(comparisonLength)).c_str(), nullptr, 10);
      if (!zeroSamplesWill(comparison, value)) mode |= GLUT_MULTISAMPLE;
    }
  }
  return mode;
}

}  // namespace
}  // namespace glass::glut

extern "C" void glutInitDisplayString(const char* displayMode) {
  glass::glut::state().initDisplayMode = glass::glut::displayModeOfString(displayMode);
}
