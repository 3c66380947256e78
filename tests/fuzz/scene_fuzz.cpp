// Fuzz target for the scene language: any bytes, read as a scene, must give either messages or a
// picture, never a crash, a hang or a leak. The text is parsed as if it were a file in a directory
// that does not exist, so relative includes, images and models fail the way missing files do;
// a scene that parses is drawn (frame 0, and its last frame when it is animated) at 32 x 32,
// with the points of its chaos games bounded (below).
// Inputs that start with the Wings3D header are .wings model files instead: read, then each
// object rounded sharp and with a radius within its limit, and tessellated.
//
// Built two ways (tests/fuzz/CMakeLists.txt): with libFuzzer when GLASS_FUZZ is on (clang), and
// always as a replay program that runs the stored corpus, so a crash found once stays fixed.
#include "glass/scene/parser.h"
#include "glass/scene/render.h"
#include "glass/scene/wings_file.h"

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <span>
#include <string>
#include <variant>

namespace {

// A chaos game's cost is linear in the points it asks for (up to kMaxChaosGamePoints, 200
// million), which the parser accepts: a few million take seconds under the fuzzer's
// instrumentation and say nothing more than a few thousand. Drawn scenes play at most this many.
constexpr std::int64_t kFuzzChaosGamePoints = 20000;

void boundChaosGames(glass::scene::StatementList &statements) {
  using namespace glass::scene;
  for (Statement &statement : statements) {
    if (auto *ifs = std::get_if<Ifs>(&statement.body)) {
      ifs->points = std::min(ifs->points, kFuzzChaosGamePoints);
      boundChaosGames(ifs->base);
    } else if (auto *begin = std::get_if<Begin>(&statement.body)) {
      boundChaosGames(begin->body);
    }
  }
}

void fuzzWingsFile(std::span<const std::uint8_t> bytes) {
  using namespace glass;
  scene::WingsFile file;
  try {
    file = scene::parseWingsFile(bytes);
  } catch (const scene::WingsFileError &) {
    return;
  }
  for (const scene::WingsObject &object : file.objects) {
    try {
      const double largest = geometry::maximumRoundingRadius(object.shape);
      for (double radius : {0.0, std::min(0.1, largest / 2.0)}) {
        geometry::AdaptiveOptions options;
        options.maxDepth = 3;
        geometry::tessellateRounded(object.shape, geometry::roundMarkedEdges(object.shape, radius), options);
      }
    } catch (const geometry::RoundingError &) {
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  using namespace glass::scene;
  static const char wingsHeader[] = "#!WINGS-1.0";
  if (size >= sizeof(wingsHeader) - 1 && std::memcmp(data, wingsHeader, sizeof(wingsHeader) - 1) == 0) {
    fuzzWingsFile(std::span(data, size));
    return 0;
  }
  const std::string text(reinterpret_cast<const char *>(data), size);
  Diagnostics diagnostics;
  Program program = parseSceneText("no-such-directory/fuzz.scene", text, diagnostics);
  // Formatting the messages shows each offending line with its caret: exercise it on every input.
  const std::string messages = diagnostics.format();
  if (diagnostics.hasErrors()) return 0;
  boundChaosGames(program.statements);
  for (Definition &definition : program.definitions) boundChaosGames(definition.body);

  RenderOptions options;
  options.width = 32;
  options.height = 32;
  RenderedFrame frame;
  Diagnostics renderDiagnostics;
  renderFrame(program, 0, options, frame, renderDiagnostics);
  if (program.frames > 1) renderFrame(program, program.frames - 1, options, frame, renderDiagnostics);
  return 0;
}
