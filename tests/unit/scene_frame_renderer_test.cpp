// FrameRenderer (glass/scene/render.h): frames drawn one after another in a kept, reset context
// with kept textures and display lists are the pictures renderFrame draws in a new context, byte
// for byte, for every scene in scenes/, through changes of frame, view, camera and size.
#include <doctest/doctest.h>

#include <glass/scene/parser.h>
#include <glass/scene/render.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace glass::scene;

namespace {

std::vector<std::string> sceneFiles() {
  std::vector<std::string> files;
  for (const auto &entry : std::filesystem::directory_iterator(std::string(GLASS_SOURCE_DIR) + "/scenes"))
    if (entry.path().extension() == ".scene") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

Image renderedBy(FrameRenderer &renderer, int frame, const RenderOptions &options) {
  RenderedFrame result;
  Diagnostics diagnostics;
  REQUIRE_MESSAGE(renderer.render(frame, options, result, diagnostics), diagnostics.format());
  return result.image;
}

Image renderedNew(const Program &program, int frame, const RenderOptions &options) {
  RenderedFrame result;
  Diagnostics diagnostics;
  REQUIRE_MESSAGE(renderFrame(program, frame, options, result, diagnostics), diagnostics.format());
  return result.image;
}

bool sameBytes(const Image &a, const Image &b) {
  return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

} // namespace

TEST_CASE("FrameRenderer: every scene's frames equal renderFrame's, kept context or not") {
  const std::vector<std::string> files = sceneFiles();
  REQUIRE(files.size() >= 20);
  int keptFrames = 0;
  for (const std::string &file : files) {
    CAPTURE(file);
    Diagnostics diagnostics;
    const Program program = parseSceneFile(file, diagnostics);
    REQUIRE_MESSAGE(!diagnostics.hasErrors(), diagnostics.format());
    const int last = program.frames - 1;
    RenderOptions small;
    small.width = 96;
    small.height = 72;
    RenderOptions depth = small;
    depth.view = View::Depth;
    ViewCamera camera;  // looking at the scene's middle from a corner
    camera.eye[0] = 4;
    camera.eye[1] = 3;
    camera.eye[2] = 6;
    RenderOptions viewer = small;
    viewer.camera = &camera;
    RenderOptions larger = small;
    larger.width = 120;
    larger.height = 90;

    // The sequence a viewer goes through: the same frame again (kept), another frame, a view,
    // back to colours, a camera of its own moving, another size.
    struct Step {
      int frame;
      const RenderOptions *options;
    };
    const Step steps[] = {{0, &small},  {0, &small},  {last, &small}, {last, &small}, {0, &depth},
                          {0, &small},  {0, &viewer}, {0, &viewer},   {0, &larger},   {0, &larger}};
    FrameRenderer renderer(program);
    for (const Step &step : steps) {
      if (step.options == &viewer) camera.eye[0] += 0.5;
      CAPTURE(step.frame);
      CAPTURE(static_cast<int>(step.options->view));
      CHECK(sameBytes(renderedBy(renderer, step.frame, *step.options), renderedNew(program, step.frame, *step.options)));
    }
    keptFrames += renderer.framesKept();
  }
  // Most steps keep the context: repeats, the camera's moves, the way back from the depth view
  // does not (another view), a scene whose frames differ does not between them.
  CHECK(keptFrames >= static_cast<int>(files.size()) * 3);
}

TEST_CASE("FrameRenderer: definitions that use animated values are compiled again for each frame") {
  // A definition's colour follows a parameter; its display list holds the value it was compiled
  // with, so another frame's value needs another compile.
  Diagnostics diagnostics;
  const Program program = parseSceneText(
      "animated_definition.scene",
      "size 4 4\nframes 3\nparam red 0\nanimate red key 0 0 key 2 1\n"
      "define square\n  color $red 0 0\n  rect -1 -1 1 1\nend\nclear\ninstance square\n",
      diagnostics);
  REQUIRE_MESSAGE(!diagnostics.hasErrors(), diagnostics.format());
  FrameRenderer renderer(program);
  const RenderOptions options;
  for (int frame : {0, 2, 1, 1, 0}) {
    CAPTURE(frame);
    const Image image = renderedBy(renderer, frame, options);
    CHECK(sameBytes(image, renderedNew(program, frame, options)));
    CHECK(static_cast<int>(image.rgba[0]) == (frame == 0 ? 0 : frame == 1 ? 128 : 255));
  }
  CHECK(renderer.framesKept() == 1);
}

TEST_CASE("FrameRenderer: a definition that sets the camera follows the viewer's camera") {
  Diagnostics diagnostics;
  const Program program = parseSceneText(
      "camera_definition.scene",
      "size 16 16\ndefine view\n  perspective 40 auto 0.5 20\n  lookat 0 0 5 0 0 0 0 1 0\nend\n"
      "clear\ninstance view\ncolor 1 1 1\nrect -0.5 -0.5 0.5 0.5\n",
      diagnostics);
  REQUIRE_MESSAGE(!diagnostics.hasErrors(), diagnostics.format());
  FrameRenderer renderer(program);
  ViewCamera camera;
  RenderOptions options;
  options.camera = &camera;
  for (double x : {0.0, 1.5, 3.0}) {
    camera.eye[0] = x;
    CHECK(sameBytes(renderedBy(renderer, 0, options), renderedNew(program, 0, options)));
  }
}

TEST_CASE("FrameRenderer: a frame that fails keeps nothing, and the next is drawn anew") {
  Diagnostics diagnostics;
  const Program program = parseSceneText("renderer_test.scene",
                                         "size 8 8\nparam w 1\nclear\nline_width $w\nbegin lines\nvertex 0 0\nvertex 1 1\nend\n",
                                         diagnostics);
  REQUIRE(!diagnostics.hasErrors());
  FrameRenderer renderer(program);
  RenderOptions options;
  const Image first = renderedBy(renderer, 0, options);
  RenderOptions tooLarge;
  tooLarge.width = 20000;
  RenderedFrame result;
  Diagnostics failure;
  CHECK_FALSE(renderer.render(0, tooLarge, result, failure));
  CHECK(failure.hasErrors());
  CHECK(sameBytes(renderedBy(renderer, 0, options), first));
  CHECK(renderer.framesKept() == 0);
  CHECK(sameBytes(renderedBy(renderer, 0, options), first));
  CHECK(renderer.framesKept() == 1);

  // An error in the middle of the frame: the frame fails, and so does the next, anew.
  const Program broken = parseSceneText("broken.scene", "size 8 8\nparam w -1\nclear\nline_width $w\n", diagnostics);
  REQUIRE(!diagnostics.hasErrors());
  FrameRenderer failing(broken);
  for (int attempt = 0; attempt < 2; ++attempt) {
    Diagnostics error;
    CHECK_FALSE(failing.render(0, options, result, error));
    CHECK(error.format().find("line width") != std::string::npos);
  }
  CHECK(failing.framesKept() == 0);
}
