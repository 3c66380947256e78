// Fuzz target for the scene language: any bytes, read as a scene, must give either messages or a
// picture, never a crash, a hang or a leak. The text is parsed as if it were a file in a directory
// that does not exist, so relative includes, images and models fail the way missing files do;
// a scene that parses is drawn (frame 0, and its last frame when it is animated) at 32 x 32.
//
// Built two ways (tests/fuzz/CMakeLists.txt): with libFuzzer when GLASS_FUZZ is on (clang), and
// always as a replay program that runs the stored corpus, so a crash found once stays fixed.
#include "glass/scene/parser.h"
#include "glass/scene/render.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  using namespace glass::scene;
  const std::string text(reinterpret_cast<const char *>(data), size);
  Diagnostics diagnostics;
  const Program program = parseSceneText("no-such-directory/fuzz.scene", text, diagnostics);
  // Formatting the messages shows each offending line with its caret: exercise it on every input.
  const std::string messages = diagnostics.format();
  if (diagnostics.hasErrors()) return 0;

  RenderOptions options;
  options.width = 32;
  options.height = 32;
  RenderedFrame frame;
  Diagnostics renderDiagnostics;
  renderFrame(program, 0, options, frame, renderDiagnostics);
  if (program.frames > 1) renderFrame(program, program.frames - 1, options, frame, renderDiagnostics);
  return 0;
}
