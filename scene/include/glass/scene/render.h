// Rendering a parsed scene to pictures: one frame at a time, each as in a new GL context, with
// supersampling and the teaching views. Uses glass/context.h to make the context and glReadPixels
// to read it back, so it works on glass and, in the reference build, on Mesa.
#pragma once

#include "glass/scene/diagnostics.h"
#include "glass/scene/program.h"

#include <memory>
#include <string>

namespace glass::scene {

enum class View {
  Color,     // the picture
  Depth,     // the depth buffer as grey, stretched between the nearest and farthest depth drawn
  Overdraw,  // fragments per pixel, counted in the stencil buffer, as a heat map
  Wireframe, // every polygon in line mode
};

// An interactive viewer's camera (glass view): when given, it replaces the scene's `lookat` and
// its projection statements (`perspective`, `frustum`, `ortho`), which the frame otherwise runs.
struct ViewCamera {
  double eye[3] = {0, 0, 5}, centre[3] = {0, 0, 0}, up[3] = {0, 1, 0};
  bool orthographic = false;
  double fovy = 45.0;      // perspective: the vertical field of view in degrees
  double halfHeight = 1.0; // orthographic: half the height of the view volume
  double zNear = 0.1, zFar = 100.0;
};

// The scene's own camera as the frame ran it: its first `lookat` and `perspective`.
struct SceneCamera {
  bool hasLookAt = false;
  double lookAt[9] = {};  // eye, centre, up
  bool hasPerspective = false;
  double fovy = 0.0, zNear = 0.0, zFar = 0.0;
};

struct RenderOptions {
  int width = 0, height = 0; // 0: the scene's `size`
  // Supersampling: the frame is drawn at supersample times the size in each direction and each
  // supersample x supersample block is averaged (a box filter) into one pixel.
  int supersample = 1;
  View view = View::Color;
  long traceVertex = -1; // >= 0: follow that vertex through the pipeline
  const ViewCamera *camera = nullptr; // the viewer's camera instead of the scene's
  SceneCamera *sceneCamera = nullptr; // filled with the scene's camera when not null
};

struct RenderedFrame {
  Image image;       // RGBA8, top row first, at the requested size
  std::string notes; // what a view measured ("overdraw: up to 5 fragments a pixel"), or empty
  std::string trace; // the vertex trace, or a note that the vertex was not reached
};

// The largest framebuffer side a context accepts.
constexpr int kMaxFramebufferSide = 16384;

// Draws frame `frame` (0-based) of the program in a new context. Returns false with messages in
// `diagnostics` on a GL error, a failing context or an unsupported view.
bool renderFrame(const Program &program, int frame, const RenderOptions &options, RenderedFrame &result,
                 Diagnostics &diagnostics);

// Draws frames of one program one after another (glass view and glass render --frames draw with
// one): each is the picture renderFrame draws, byte for byte, but the GL context is kept from
// frame to frame while the size stays the same, put back in GL's initial state
// (glassResetContext) before each frame, and so are the program's textures and its definitions
// compiled into display lists while the view and the parameter values stay the same too (the
// camera may change). A frame that fails leaves nothing kept. The program must outlive the
// renderer and stay unchanged.
class FrameRenderer {
public:
  explicit FrameRenderer(const Program &program);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer &) = delete;
  FrameRenderer &operator=(const FrameRenderer &) = delete;

  // As renderFrame.
  bool render(int frame, const RenderOptions &options, RenderedFrame &result, Diagnostics &diagnostics);

  // How many of the frames rendered so far used kept textures and display lists (for tests).
  int framesKept() const { return framesKept_; }

private:
  struct Kept;
  const Program &program_;
  bool definitionsSetCamera_;  // compiled, they would keep the camera of the frame they were compiled in
  std::unique_ptr<Kept> kept_;
  int framesKept_ = 0;
};

// Writes the picture (alpha left out) as PNG, JPEG, BMP or TGA, chosen by the file name's
// extension. The file is written whole or not at all: a temporary file in the same directory is
// renamed over `path` when complete. Returns false and a reason on failure.
bool writeImage(const std::string &path, const Image &image, std::string &reason);

// True when writeImage knows the extension of `path`.
bool isSupportedImagePath(const std::string &path);

} // namespace glass::scene
