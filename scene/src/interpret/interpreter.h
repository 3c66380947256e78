// Replays a parsed scene into the current GL context, one statement after another, each as the
// GL calls docs/scene-format.md gives for it. Only the public GL, GLU and GLUT API is used, so
// the same code draws with glass or with Mesa.
#pragma once

#include "glass/scene/diagnostics.h"
#include "glass/scene/program.h"
#include "glass/scene/frame_values.h"

#include <GL/gl.h>

#include <iosfwd>
#include <memory>
#include <vector>

namespace glass::scene {

class VertexTracer;
struct ViewCamera;
struct SceneCamera;

// What a frame makes in its context besides the picture: the texture objects of the program's
// textures and the display lists of its definitions. A frame given those an earlier frame of the
// same program made in the same context, with the same parameter values and options, uses them
// instead of making them again (FrameRenderer, glass/scene/render.h); a shadow map's texture is
// made again each frame, since its depth is the frame's own.
struct FrameResources {
  bool made = false;
  std::vector<GLuint> textures; // program.textures[i]'s texture object
  GLuint listBase = 0;          // definition i is display list listBase + i; 0: not compiled
};

struct InterpreterOptions {
  // Pixel measures in the scene (viewport, scissor, line width, point size) are in pixels of the
  // scene's `size`; drawn at another size or supersampled, they are scaled so that the frame is
  // the same picture at another resolution: x by scaleX, y by scaleY, widths by their geometric
  // mean.
  double scaleX = 1.0, scaleY = 1.0;
  // Teaching views: wireframe forces glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); countOverdraw
  // makes the stencil buffer count fragments (the scene's own stencil statements are skipped).
  bool wireframe = false;
  bool countOverdraw = false;
  // Definitions become display lists; when false their statements are replayed at each
  // instance (the vertex trace needs to see every vertex).
  bool compileDefinitions = true;
  VertexTracer *tracer = nullptr;
  // glass view: the viewer's camera replaces the scene's lookat and projection; the scene's own
  // camera is reported (glass/scene/render.h).
  const ViewCamera *camera = nullptr;
  SceneCamera *sceneCamera = nullptr;
  // Textures and definitions kept from an earlier frame in this context, or null: made anew.
  FrameResources *resources = nullptr;
  // Where warnings about the GL go (a missing extension); null: into the diagnostics only.
};

class Interpreter {
public:
  Interpreter(const Program &program, const InterpreterOptions &options);
  ~Interpreter();
  Interpreter(const Interpreter &) = delete;
  Interpreter &operator=(const Interpreter &) = delete;

  // Draws the frame whose parameter values are `values` (evaluateParameters) into the current
  // context, which must be in GL's initial state (new, or reset by glassResetContext) and of
  // the size the frame is drawn at. Returns false when a GL error or a bad value stopped it; the
  // messages are in `diagnostics`.
  bool drawFrame(const FrameValues &values, Diagnostics &diagnostics);

  class Executor; // the statement-by-statement part (executor.h)

private:
  const Program &program_;
  InterpreterOptions options_;
};

} // namespace glass::scene
