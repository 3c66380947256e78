// glClear queued in the tiled rasterizer (TiledRasterizer::clear): each tile runs its part of the
// clear in order with the primitives of its bin, on whichever thread takes the tile. Here random
// triangles, lines and points written into a framebuffer are interleaved with clears of random
// rectangles (colour with every colour mask, depth, stencil through a write mask); with 1, 2, 3
// and 8 threads the framebuffer must hold exactly the bytes of drawing and clearing everything in
// order on one thread without tiles. Half of the triangles and lines are small, and so are the
// points: with one thread those are drawn as they come, between the binned large ones and clears,
// which must still reach each pixel in order. Each triangle has settings of its own, as draws
// change them (bounds cut by a scissor box, how many varyings, which way it faces, its depth
// offset, whether depth is used and tested early), often the same as the triangle before, as
// within a draw: a bin keeps the settings of a run of triangles once. With one thread, small
// triangles scattered over the window are binned after all, and those of a mesh (each next to the
// one before) drawn at once: long runs of both, interleaved with clears and lines, must give the
// same bytes too.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "glass/raster/framebuffer.h"
#include "glass/raster/framebuffer_clear.h"
#include "glass/raster/line.h"
#include "glass/raster/tiled_rasterizer.h"
#include "glass/raster/triangle.h"
#include "raster_test_support.h"

using namespace glass::raster;
using glass::raster::test::windowVertex;

namespace {

constexpr int kWidth = 301, kHeight = 203;  // not multiples of the tile size

// Writes each fragment's colour (varyings 0 to 3, in [0, 1], each plus the last varying, with
// more than four) and depth, replacing what was there, and adds 1 to the stencil (2 for a triangle
// facing back): the order in which fragments and clears reach a pixel decides its bytes.
class WritingSink final : public FragmentSink {
 public:
  explicit WritingSink(Framebuffer& fb) : fb_(fb) {}
  void processFragments(const FragmentBatch& batch) override {
    for (int i = 0; i < batch.count; ++i) {
      const Fragment& f = batch.fragments[i];
      uint8_t* pixel = fb_.colorAt(f.x, f.y);
      const float last = batch.varyingCount > 4 ? f.varyings[batch.varyingCount - 1] : 0.0f;
      for (int c = 0; c < 4; ++c) pixel[c] = static_cast<uint8_t>((f.varyings[c] + last) * 127.0f);
      *fb_.depthAt(f.x, f.y) = f.depth;
      *fb_.stencilAt(f.x, f.y) += batch.frontFacing ? 1 : 2;
    }
  }

 private:
  Framebuffer& fb_;
};

// One step of the test's program: a primitive or a clear.
struct Step {
  enum Kind { Triangle, Line, Point, Clear } kind;
  WindowVertex v[3];
  TriangleSettings triangle;  // its earlyDepth.buffer is set where it is drawn, when
  bool earlyDepthTest;        // this is true
  ClearRequest clear;
};

// The settings of a triangle step drawn into `fb`.
TriangleSettings settingsIn(const Step& step, const Framebuffer& fb) {
  TriangleSettings s = step.triangle;
  if (step.earlyDepthTest) s.earlyDepth = EarlyDepthTest{&fb, DepthCompare::Less};
  return s;
}

WindowVertex coloured(float x, float y, std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  WindowVertex v = windowVertex(x, y, unit(random));
  v.invW = 0.25f + unit(random);  // perspective-correct varyings: each tile's setup must give the planes of the whole
  for (float& varying : v.varyings) varying = unit(random);
  return v;
}

// A step's three vertices, coloured: anywhere in and about the window, or (half of the time)
// within a box of `small` x `small` pixels there, which one thread draws at once.
// A small triangle (within `size` x `size` pixels) about (cx, cy).
void placeSmall(WindowVertex (&v)[3], float cx, float cy, float size, std::mt19937& random) {
  std::uniform_real_distribution<float> near(-0.5f * size, 0.5f * size);
  for (WindowVertex& vertex : v) vertex = coloured(cx + near(random), cy + near(random), random);
}

void placeVertices(WindowVertex (&v)[3], float small, std::mt19937& random) {
  std::uniform_real_distribution<float> x(-40.0f, kWidth + 40.0f), y(-40.0f, kHeight + 40.0f);
  const bool within = std::uniform_int_distribution<int>(0, 1)(random) == 1;
  const float cx = x(random), cy = y(random);
  if (within) return placeSmall(v, cx, cy, small, random);
  for (WindowVertex& vertex : v) vertex = coloured(x(random), y(random), random);
}

TriangleSettings triangleSettings() {
  TriangleSettings s;
  s.bounds = PixelRect{0, 0, kWidth, kHeight};
  s.varyingCount = 4;
  return s;
}

// A rectangle of pixels anywhere about the window, cut to it (as a scissor box cuts the bounds).
PixelRect randomRect(std::mt19937& random) {
  std::uniform_int_distribution<int> px(-20, kWidth + 20), py(-20, kHeight + 20);
  int x0 = px(random), x1 = px(random), y0 = py(random), y1 = py(random);
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  return PixelRect{std::max(x0, 0), std::max(y0, 0), std::min(x1, kWidth), std::min(y1, kHeight)};
}

// The triangle settings of a new draw: the defaults but for at most one setting, so that two
// draws in a row may differ in any one alone. The early depth test is `earlyDepthTest`.
TriangleSettings newDrawSettings(std::mt19937& random, bool& earlyDepthTest) {
  TriangleSettings s = triangleSettings();
  earlyDepthTest = false;
  switch (std::uniform_int_distribution<int>(0, 4)(random)) {
    case 0: break;
    case 1: s.bounds = randomRect(random); break;
    case 2: s.varyingCount = 7; break;
    case 3: s.depthUsed = false; break;
    case 4: earlyDepthTest = true; break;
  }
  return s;
}

std::vector<Step> randomProgram(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> x(-40.0f, kWidth + 40.0f), y(-40.0f, kHeight + 40.0f);
  std::uniform_int_distribution<int> kind(0, 9), bit(0, 1), byte(0, 255);
  std::vector<Step> steps;
  TriangleSettings triangle = triangleSettings();  // the settings of the draw
  bool earlyDepthTest = false;
  for (int i = 0; i < 120; ++i) {
    Step s{};
    const int k = kind(random);
    if (k < 5) {
      s.kind = Step::Triangle;
      placeVertices(s.v, 60.0f, random);
      if (bit(random)) triangle = newDrawSettings(random, earlyDepthTest);  // half begin a new draw
      s.triangle = triangle;
      s.earlyDepthTest = earlyDepthTest;
      // These two change from triangle to triangle within a draw.
      s.triangle.frontFacing = bit(random) == 1;
      s.triangle.depthBias = bit(random) ? std::uniform_real_distribution<double>(-0.01, 0.01)(random) : 0.0;
    } else if (k < 7) {
      s.kind = Step::Line;
      placeVertices(s.v, 40.0f, random);
    } else if (k < 8) {
      s.kind = Step::Point;
      s.v[0] = coloured(x(random), y(random), random);
    } else {
      s.kind = Step::Clear;
      ClearRequest& c = s.clear;
      // A scissor box: any rectangle, clamped to the framebuffer as glClear clamps it.
      c.rect = randomRect(random);
      if (bit(random)) c.rect = PixelRect{0, 0, kWidth, kHeight};
      c.clearColor = bit(random);
      for (int ch = 0; ch < 4; ++ch) {
        c.color[ch] = static_cast<uint8_t>(byte(random));
        c.colorMask[ch] = bit(random) || bit(random);
      }
      c.clearDepth = bit(random);
      c.depth = static_cast<uint32_t>(byte(random)) << 16;
      c.clearStencil = bit(random);
      c.stencil = static_cast<uint8_t>(byte(random));
      c.stencilWriteMask = static_cast<uint8_t>(byte(random));
    }
    steps.push_back(s);
  }
  return steps;
}

// Runs of small triangles, scattered over the window, then walking across it as a mesh's do (each
// a few pixels from the one before), then scattered again, with a clear or a line now and then.
std::vector<Step> scatteredThenMeshProgram(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> x(-10.0f, kWidth + 10.0f), y(-10.0f, kHeight + 10.0f);
  std::uniform_real_distribution<float> stepAlong(-3.0f, 4.0f);
  std::uniform_int_distribution<int> percent(0, 99), byte(0, 255);
  std::vector<Step> steps;
  float meshX = 5.0f, meshY = 5.0f;
  bool earlyDepthTest = false;
  TriangleSettings triangle = triangleSettings();
  for (int i = 0; i < 600; ++i) {
    Step s{};
    const int p = percent(random);
    if (p < 4) {
      s.kind = Step::Clear;
      s.clear.rect = randomRect(random);
      s.clear.clearColor = s.clear.clearDepth = true;
      for (uint8_t& c : s.clear.color) c = static_cast<uint8_t>(byte(random));
      for (bool& m : s.clear.colorMask) m = true;
      s.clear.depth = static_cast<uint32_t>(byte(random)) << 16;
    } else if (p < 8) {
      s.kind = Step::Line;
      placeSmall(s.v, x(random), y(random), 30.0f, random);
    } else {
      s.kind = Step::Triangle;
      if (i >= 200 && i < 400) {  // the mesh: across the window row by row
        meshX += stepAlong(random);
        if (meshX > kWidth) meshX = 0.0f, meshY += 7.0f;
        placeSmall(s.v, meshX, std::fmod(meshY, static_cast<float>(kHeight)), 8.0f, random);
      } else {
        placeSmall(s.v, x(random), y(random), 12.0f, random);
      }
      if (p < 10) triangle = newDrawSettings(random, earlyDepthTest);
      s.triangle = triangle;
      s.earlyDepthTest = earlyDepthTest;
    }
    steps.push_back(s);
  }
  return steps;
}

// Tiny triangles about the tiles' borders (and pixel centres there), under changing bounds: the
// tiled rasterizer puts a triangle whose corners can only reach one tile's pixels in that bin
// from its corners' coordinates, before snapping, with a pixel to spare; those about a border go
// to every tile they reach. Some have no area (a corner twice, or three in a line), some corners
// cannot be rasterized (NaN, infinite, beyond 2^19 pixels).
std::vector<Step> tileBorderProgram(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> percent(0, 99), borderX(0, kWidth / kTileSize), borderY(0, kHeight / kTileSize);
  std::uniform_int_distribution<int> sub(-3 * 512, 3 * 512);  // in 1/512 of a pixel
  std::uniform_real_distribution<float> near(-1.5f, 1.5f);
  const float unusable[4] = {std::nanf(""), INFINITY, -INFINITY, 1.0e7f};
  std::vector<Step> steps;
  TriangleSettings triangle = triangleSettings();
  bool earlyDepthTest = false;
  for (int i = 0; i < 800; ++i) {
    Step s{};
    s.kind = Step::Triangle;
    const int p = percent(random);
    // About a border's crossing, or (a quarter of the time) about a border alone, on either side.
    const float cx = static_cast<float>(kTileSize * borderX(random)) + static_cast<float>(sub(random)) / 512.0f;
    const float cy = static_cast<float>(kTileSize * borderY(random)) + static_cast<float>(sub(random)) / 512.0f;
    for (WindowVertex& vertex : s.v) {
      // Half the corners on pixel centres or on the 1/512 grid (where snapping ties).
      float x = cx + near(random), y = cy + near(random);
      if (percent(random) < 50) x = std::round(x * 2.0f) / 2.0f;
      if (percent(random) < 50) y = std::round(y * 512.0f) / 512.0f;
      if (percent(random) < 20) x = std::round(x * 512.0f) / 512.0f;
      vertex = coloured(x, y, random);
    }
    if (p < 10) s.v[2] = s.v[percent(random) % 2];  // a corner twice
    else if (p < 15) s.v[2] = coloured(2.0f * s.v[1].x - s.v[0].x, 2.0f * s.v[1].y - s.v[0].y, random);  // in a line
    else if (p < 18) s.v[percent(random) % 3].x = unusable[percent(random) % 4];
    else if (p < 21) s.v[percent(random) % 3].y = unusable[percent(random) % 4];
    if (p % 7 == 0) triangle = newDrawSettings(random, earlyDepthTest);
    s.triangle = triangle;
    s.earlyDepthTest = earlyDepthTest;
    steps.push_back(s);
  }
  return steps;
}

LineSettings lineSettings() {
  LineSettings s;
  s.bounds = PixelRect{0, 0, kWidth, kHeight};
  s.varyingCount = 4;
  s.width = 3.0f;
  s.framebufferHeight = kHeight;
  return s;
}
PointSettings pointSettings() {
  PointSettings s;
  s.bounds = PixelRect{0, 0, kWidth, kHeight};
  s.varyingCount = 4;
  s.size = 5.0f;
  return s;
}

// The framebuffer's colour, depth and stencil bytes, one after the other.
std::vector<uint8_t> contents(const Framebuffer& fb) {
  std::vector<uint8_t> bytes;
  for (int y = 0; y < kHeight; ++y) {
    const auto* color = fb.colorAt(0, y);
    const auto* depth = reinterpret_cast<const uint8_t*>(fb.depthAt(0, y));
    bytes.insert(bytes.end(), color, color + 4 * kWidth);
    bytes.insert(bytes.end(), depth, depth + 4 * kWidth);
    bytes.insert(bytes.end(), fb.stencilAt(0, y), fb.stencilAt(0, y) + kWidth);
  }
  return bytes;
}

// Draws and clears everything in order, on this thread, without tiles.
std::vector<uint8_t> drawnInOrder(const std::vector<Step>& steps) {
  Framebuffer fb(kWidth, kHeight);
  WritingSink sink(fb);
  for (Step s : steps) {
    switch (s.kind) {
      case Step::Triangle: {
        TriangleSetup setup;
        if (setupTriangle(s.v[0], s.v[1], s.v[2], settingsIn(s, fb), setup))
          rasterizeTriangle(setup, sink);
        break;
      }
      case Step::Line: rasterizeLine(s.v[0], s.v[1], lineSettings(), sink); break;
      case Step::Point: rasterizePoint(s.v[0], pointSettings(), sink); break;
      case Step::Clear:
        s.clear.target = &fb;
        clearFramebuffer(s.clear, PixelRect{0, 0, kWidth, kHeight});
        break;
    }
  }
  return contents(fb);
}

std::vector<uint8_t> drawnInTiles(const std::vector<Step>& steps, int threads) {
  Framebuffer fb(kWidth, kHeight);
  WritingSink sink(fb);
  TiledRasterizer tiles(fb, threads);
  for (Step s : steps) {
    switch (s.kind) {
      case Step::Triangle: tiles.triangle(s.v[0], s.v[1], s.v[2], settingsIn(s, fb), sink); break;
      case Step::Line: tiles.line(s.v[0], s.v[1], lineSettings(), sink); break;
      case Step::Point: tiles.point(s.v[0], pointSettings(), sink); break;
      case Step::Clear:
        s.clear.target = &fb;
        tiles.clear(s.clear);
        break;
    }
  }
  tiles.finish();
  return contents(fb);
}

}  // namespace

TEST_CASE("clears queued in tiles give the bytes of clearing in order, at any thread count") {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const std::vector<Step> steps = randomProgram(seed);
    const std::vector<uint8_t> expected = drawnInOrder(steps);
    for (const int threads : {1, 2, 3, 8}) {
      CAPTURE(seed);
      CAPTURE(threads);
      CHECK(drawnInTiles(steps, threads) == expected);
    }
  }
}

TEST_CASE("small triangles scattered, then a mesh's, then scattered: the bytes of drawing in order") {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const std::vector<Step> steps = scatteredThenMeshProgram(seed);
    const std::vector<uint8_t> expected = drawnInOrder(steps);
    for (const int threads : {1, 2}) {
      CAPTURE(seed);
      CAPTURE(threads);
      CHECK(drawnInTiles(steps, threads) == expected);
    }
  }
}

TEST_CASE("a tiled rasterizer with only clears queued holds no primitive") {
  Framebuffer fb(kWidth, kHeight);
  WritingSink sink(fb);
  TiledRasterizer tiles(fb, 2);
  ClearRequest clear;
  clear.target = &fb;
  clear.rect = PixelRect{0, 0, kWidth, kHeight};
  clear.clearDepth = true;
  clear.depth = 0xFFFFFF;
  tiles.clear(clear);
  CHECK_FALSE(tiles.idle());
  CHECK_FALSE(tiles.primitivesQueued());
  tiles.triangle(windowVertex(10, 10), windowVertex(200, 20), windowVertex(50, 150), triangleSettings(), sink);
  CHECK(tiles.primitivesQueued());
  tiles.finish();
  CHECK(tiles.idle());
  CHECK_FALSE(tiles.primitivesQueued());
  CHECK(*fb.depthAt(kWidth - 1, kHeight - 1) == 0xFFFFFFu);
}

// With one thread a small triangle is drawn at once, after the bins of the tiles under it have
// run. When that leaves no bin with anything in it, nothing is queued: primitivesQueued() must
// say so, or the draw pipeline would keep an earlier draw's fragment settings for the next draw
// (it changes them only when no primitive is queued).
TEST_CASE("one thread: a small triangle that runs every queued bin leaves nothing queued") {
  Framebuffer fb(kWidth, kHeight);
  WritingSink sink(fb);
  TiledRasterizer tiles(fb, 1);
  // A box of 98 x 58 pixels over the first two tiles of the bottom row: binned.
  tiles.triangle(windowVertex(2, 2), windowVertex(100, 2), windowVertex(2, 60), triangleSettings(), sink);
  CHECK(tiles.primitivesQueued());
  // 30 x 30 pixels over the same two tiles: drawn at once, after both bins.
  tiles.triangle(windowVertex(50, 10), windowVertex(80, 10), windowVertex(50, 40), triangleSettings(), sink);
  CHECK(tiles.idle());
  CHECK_FALSE(tiles.primitivesQueued());
  // Over one of them only, with the other still queued: still queued.
  tiles.triangle(windowVertex(2, 2), windowVertex(100, 2), windowVertex(2, 60), triangleSettings(), sink);
  tiles.triangle(windowVertex(10, 10), windowVertex(30, 10), windowVertex(10, 30), triangleSettings(), sink);
  CHECK_FALSE(tiles.idle());
  CHECK(tiles.primitivesQueued());
  tiles.finish();
  CHECK(tiles.idle());
  CHECK_FALSE(tiles.primitivesQueued());
}

// Small triangles scattered over the window are binned (each drawn at once would fetch its rows
// from memory); a mesh's, each in the tile of the one before, are drawn at once again.
TEST_CASE("one thread: scattered small triangles are binned, a mesh's drawn at once") {
  Framebuffer fb(kWidth, kHeight);
  WritingSink sink(fb);
  TiledRasterizer tiles(fb, 1);
  std::mt19937 random(7);
  auto smallAt = [&](float cx, float cy) {
    WindowVertex v[3];
    placeSmall(v, cx, cy, 10.0f, random);
    tiles.triangle(v[0], v[1], v[2], triangleSettings(), sink);
  };
  // Corners of the window in turn: every triangle in another tile than the one before.
  const float corners[4][2] = {{10, 10}, {kWidth - 10, 10}, {kWidth - 10, kHeight - 10}, {10, kHeight - 10}};
  for (int i = 0; i < 100; ++i) smallAt(corners[i % 4][0], corners[i % 4][1]);
  CHECK(tiles.primitivesQueued());
  tiles.finish();
  CHECK(tiles.idle());
  // 100 about one spot: once most of the last 64 stayed in their tile, drawn at once, after that
  // tile's bin (the only one with anything queued).
  for (int i = 0; i < 100; ++i) smallAt(100.0f + 0.1f * static_cast<float>(i), 100.0f);
  CHECK(tiles.idle());
  CHECK_FALSE(tiles.primitivesQueued());
}

TEST_CASE("tiny triangles about the tiles' borders, some of no area or unusable: the bytes of drawing in order") {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const std::vector<Step> steps = tileBorderProgram(seed);
    const std::vector<uint8_t> expected = drawnInOrder(steps);
    for (const int threads : {1, 2, 3}) {
      CAPTURE(seed);
      CAPTURE(threads);
      CHECK(drawnInTiles(steps, threads) == expected);
    }
  }
}
