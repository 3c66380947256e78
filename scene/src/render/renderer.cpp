// One frame: a fresh context, the interpreter, the read-back, the teaching views, supersampling.
#include "gl_api.h"
#include "glass/scene/render.h"
#include "interpret/interpreter.h"
#include "interpret/vertex_trace.h"
#include "render/views.h"

#include <glass/context.h>

#include <utility>

namespace glass::scene {

namespace {

// Owns the GL context of one frame.
class FrameContext {
public:
  FrameContext(int width, int height) : context_(glassCreateContext(width, height)) {
    if (context_ != nullptr && glassMakeCurrent(context_) == 0) {
      glassDestroyContext(context_);
      context_ = nullptr;
    }
  }
  ~FrameContext() {
    if (context_ != nullptr) {
      glassMakeCurrent(nullptr);
      glassDestroyContext(context_);
    }
  }
  FrameContext(const FrameContext &) = delete;
  FrameContext &operator=(const FrameContext &) = delete;
  bool ok() const { return context_ != nullptr; }

private:
  GlassContext *context_;
};

} // namespace

bool renderFrame(const Program &program, int frame, const RenderOptions &options, RenderedFrame &result,
                 Diagnostics &diagnostics) {
  const int width = options.width > 0 ? options.width : program.width;
  const int height = options.height > 0 ? options.height : program.height;
  const int factor = options.supersample < 1 ? 1 : options.supersample;
  const long long drawWidth = static_cast<long long>(width) * factor;
  const long long drawHeight = static_cast<long long>(height) * factor;
  if (drawWidth > kMaxFramebufferSide || drawHeight > kMaxFramebufferSide) {
    diagnostics.error({}, std::to_string(width) + "x" + std::to_string(height) + " supersampled " +
                              std::to_string(factor) + " times needs a " + std::to_string(drawWidth) + "x" +
                              std::to_string(drawHeight) + " framebuffer; the largest is " +
                              std::to_string(kMaxFramebufferSide) + " a side");
    return false;
  }
  const int w = static_cast<int>(drawWidth), h = static_cast<int>(drawHeight);
  FrameContext context(w, h);
  if (!context.ok()) {
    diagnostics.error({}, "cannot create a " + std::to_string(w) + "x" + std::to_string(h) + " GL context");
    return false;
  }

  VertexTracer tracer(options.traceVertex);
  tracer.setPixelScale(factor); // window coordinates in pixels of the output picture
  InterpreterOptions interpreterOptions;
  interpreterOptions.scaleX = static_cast<double>(w) / program.width;
  interpreterOptions.scaleY = static_cast<double>(h) / program.height;
  interpreterOptions.wireframe = options.view == View::Wireframe;
  interpreterOptions.countOverdraw = options.view == View::Overdraw;
  interpreterOptions.tracer = options.traceVertex >= 0 ? &tracer : nullptr;
  interpreterOptions.compileDefinitions = options.traceVertex < 0;
  Interpreter interpreter(program, interpreterOptions);
  if (!interpreter.drawFrame(frame, diagnostics)) return false;

  if (options.traceVertex >= 0) {
    result.trace = tracer.found() ? tracer.report()
                                  : "vertex " + std::to_string(options.traceVertex) + " was not reached: the scene sends " +
                                        std::to_string(tracer.count()) +
                                        " vertices that the trace counts (vertex, rect, mesh, model, ifs points; "
                                        "GLU, GLUT and evaluator shapes are not counted)\n";
  }

  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  Image image;
  switch (options.view) {
  case View::Color:
  case View::Wireframe: {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    image = imageFromGlRows(std::move(rgba), w, h);
    break;
  }
  case View::Depth: {
    std::vector<float> depth(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 1.0f);
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    image = depthImage(depth, w, h, result.notes);
    break;
  }
  case View::Overdraw: {
    std::vector<std::uint8_t> counts(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
    glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, counts.data());
    image = overdrawImage(counts, w, h, result.notes);
    break;
  }
  }
  if (GLenum error = glGetError(); error != GL_NO_ERROR) {
    diagnostics.error({}, "this GL could not read the " +
                              std::string(options.view == View::Depth      ? "depth buffer (glReadPixels GL_DEPTH_COMPONENT)"
                                          : options.view == View::Overdraw ? "stencil buffer (glReadPixels GL_STENCIL_INDEX)"
                                                                           : "colour buffer (glReadPixels GL_RGBA)"));
    return false;
  }
  result.image = boxDownsample(std::move(image), factor);
  return true;
}

} // namespace glass::scene
