// The scene renderer on glass: pixels of small scenes, the teaching views, supersampling,
// animation and the vertex trace, checked against values worked out by hand.
#include <doctest/doctest.h>

#include <glass/scene/parser.h>
#include <glass/scene/render.h>

#include <array>
#include <cstdint>
#include <string>

using namespace glass::scene;

namespace {

Program parse(const std::string &text, ParseOptions options = {}) {
  Diagnostics diagnostics;
  Program program = parseSceneText("render_test.scene", text, diagnostics, options);
  REQUIRE_MESSAGE(!diagnostics.hasErrors(), diagnostics.format());
  return program;
}

RenderedFrame render(const Program &program, RenderOptions options = {}, int frame = 0) {
  RenderedFrame result;
  Diagnostics diagnostics;
  REQUIRE_MESSAGE(renderFrame(program, frame, options, result, diagnostics), diagnostics.format());
  return result;
}

// The colour at (x, y), x from the left, y from the top.
std::array<int, 3> pixel(const Image &image, int x, int y) {
  const std::uint8_t *p = &image.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                       static_cast<std::size_t>(x)) * 4];
  return {p[0], p[1], p[2]};
}

} // namespace

TEST_CASE("scene render: statements become pixels, top row first") {
  // The lower half of a 4 x 4 picture red, the upper half cleared to blue.
  Program program = parse("size 4 4\nclear_color 0 0 1\nclear\northo 0 4 0 4\ncolor 1 0 0\nrect 0 0 4 2\n");
  RenderedFrame frame = render(program);
  REQUIRE(frame.image.width == 4);
  REQUIRE(frame.image.height == 4);
  CHECK(pixel(frame.image, 0, 0) == std::array<int, 3>{0, 0, 255});
  CHECK(pixel(frame.image, 3, 1) == std::array<int, 3>{0, 0, 255});
  CHECK(pixel(frame.image, 0, 2) == std::array<int, 3>{255, 0, 0});
  CHECK(pixel(frame.image, 3, 3) == std::array<int, 3>{255, 0, 0});
}

TEST_CASE("scene render: --size scales the scene's viewports with the picture") {
  // The right half of the scene's 4 x 2 picture is a viewport filled white; at 8 x 4 it is still
  // the right half.
  Program program = parse("size 4 2\nclear\nviewport 2 0 2 2\northo 0 1 0 1\nrect 0 0 1 1\n");
  RenderOptions options;
  options.width = 8;
  options.height = 4;
  RenderedFrame frame = render(program, options);
  CHECK(pixel(frame.image, 3, 2) == std::array<int, 3>{0, 0, 0});
  CHECK(pixel(frame.image, 4, 2) == std::array<int, 3>{255, 255, 255});
  CHECK(pixel(frame.image, 7, 0) == std::array<int, 3>{255, 255, 255});
}

TEST_CASE("scene render: supersampling averages N x N samples with a box filter") {
  // One output pixel; white covers the left half of it: at --ssaa 2, two of four samples are
  // white, (2 * 255 + 2) / 4 = 128 (rounded to nearest).
  Program program = parse("size 1 1\nclear\northo 0 2 0 2\nrect 0 0 1 2\n");
  RenderOptions options;
  options.supersample = 2;
  RenderedFrame frame = render(program, options);
  CHECK(pixel(frame.image, 0, 0) == std::array<int, 3>{128, 128, 128});
  options.supersample = 4; // 8 of 16 samples: the same average
  CHECK(pixel(render(program, options).image, 0, 0) == std::array<int, 3>{128, 128, 128});
}

TEST_CASE("scene render: the overdraw view counts fragments per pixel in the stencil buffer") {
  // Three full-picture rects, and a fourth over the left half: 4 fragments there, 3 elsewhere,
  // whatever the depth test and the scene's own stencil statements say.
  Program program = parse("size 4 2\northo 0 4 0 2\nenable depth_test stencil_test\nstencil_func never 0 255\n"
                          "rect 0 0 4 2\nrect 0 0 4 2\nrect 0 0 4 2\nrect 0 0 2 2\n");
  RenderOptions options;
  options.view = View::Overdraw;
  RenderedFrame frame = render(program, options);
  CHECK(pixel(frame.image, 0, 0) == std::array<int, 3>{120, 210, 0}); // 4: yellow-green
  CHECK(pixel(frame.image, 3, 1) == std::array<int, 3>{0, 180, 120}); // 3: green
  CHECK(frame.notes.find("up to 4 fragments in a pixel") != std::string::npos);
}

TEST_CASE("scene render: the depth view stretches the drawn depths from black to white") {
  // Depth 0.25 on the left, 0.75 on the right (ortho near -1, far 1: window z = (1 - z) / 2),
  // nothing in the top row: black, white, and white background.
  Program program = parse("size 2 2\northo 0 2 0 2 -1 1\nenable depth_test\n"
                          "begin quads\nvertex 0 0 0.5\nvertex 1 0 0.5\nvertex 1 1 0.5\nvertex 0 1 0.5\nend\n"
                          "begin quads\nvertex 1 0 -0.5\nvertex 2 0 -0.5\nvertex 2 1 -0.5\nvertex 1 1 -0.5\nend\n");
  RenderOptions options;
  options.view = View::Depth;
  RenderedFrame frame = render(program, options);
  CHECK(pixel(frame.image, 0, 1) == std::array<int, 3>{0, 0, 0});
  CHECK(pixel(frame.image, 1, 1) == std::array<int, 3>{255, 255, 255});
  CHECK(pixel(frame.image, 0, 0) == std::array<int, 3>{255, 255, 255});
  CHECK(frame.notes.find("between 0.250000 (black) and 0.750000 (white)") != std::string::npos);
}

TEST_CASE("scene render: animated parameters and --set change the frame") {
  const std::string text = "size 1 1\nframes 11\nparam red 1\nanimate red key 0 0 key 10 1\n"
                           "ortho 0 1 0 1\ncolor $red 0 0\nrect 0 0 1 1\n";
  Program program = parse(text);
  CHECK(pixel(render(program, {}, 0).image, 0, 0)[0] == 0);
  CHECK(pixel(render(program, {}, 5).image, 0, 0)[0] == 128); // 0.5 * 255 = 127.5, rounded up by GL
  CHECK(pixel(render(program, {}, 10).image, 0, 0)[0] == 255);
  ParseOptions set;
  set.overrides = {{"red", "0.2"}};
  Program fixed = parse(text, set);
  CHECK(pixel(render(fixed, {}, 10).image, 0, 0)[0] == 51); // --set holds over the animation
}

TEST_CASE("scene render: the vertex trace follows a vertex through every stage") {
  // The vertex (1, 1) translated by (1, 0) under ortho [0, 4] on a 40 x 20 picture: eye (2, 1),
  // clip = NDC (0, 0), window (20, 10); lit by a directional light straight on.
  Program program = parse("size 40 20\northo 0 4 0 2 -1 1\nenable lighting light0\n"
                          "light 0 position 0 0 1 0 diffuse 1 1 1\nmaterial diffuse 0.5 0.25 1 ambient 0 0 0\n"
                          "light_model ambient 0 0 0\ntranslate 1 0 0\n"
                          "begin points\nnormal 0 0 1\nvertex 0 0\nvertex 1 1\nend\n");
  RenderOptions options;
  options.traceVertex = 1;
  RenderedFrame frame = render(program, options);
  CAPTURE(frame.trace);
  CHECK(frame.trace.find("vertex 1, sent by 'vertex' at render_test.scene:") != std::string::npos);
  CHECK(frame.trace.find("eye     (   2.000000,    1.000000,    0.000000,    1.000000)") != std::string::npos);
  CHECK(frame.trace.find("ndc     (   0.000000,    0.000000,    0.000000)") != std::string::npos);
  CHECK(frame.trace.find("window  (  20.000000,   10.000000,    0.500000)") != std::string::npos);
  // Diffuse only: material times light, n.L = 1; alpha is the material's diffuse alpha.
  CHECK(frame.trace.find("colour  (   0.500000,    0.250000,    1.000000,    1.000000)   lit") != std::string::npos);

  options.traceVertex = 2;
  CHECK(render(program, options).trace.find("vertex 2 was not reached: the scene sends 2 vertices") != std::string::npos);
}

TEST_CASE("scene render: a GL error stops the frame at the statement that raised it") {
  std::string text = "size 2 2\n";
  for (int i = 0; i < 40; ++i) text += "push\n";
  for (int i = 0; i < 40; ++i) text += "pop\n";
  Program program = parse(text);
  RenderedFrame result;
  Diagnostics diagnostics;
  CHECK_FALSE(renderFrame(program, 0, {}, result, diagnostics));
  CHECK(diagnostics.format().find("error: the GL reported GL_STACK_OVERFLOW from glPushMatrix/glPushAttrib") !=
        std::string::npos);
}
