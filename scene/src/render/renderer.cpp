// One frame: its context (new, or kept from the frame before and reset), the interpreter, the
// read-back, the teaching views, supersampling.
#include "gl_api.h"
#include "glass/scene/render.h"
#include "interpret/interpreter.h"
#include "interpret/vertex_trace.h"
#include "render/views.h"

#include <glass/context.h>

#include <type_traits>
#include <utility>
#include <variant>

namespace glass::scene {

namespace {

// Whether a definition sets the camera: compiled into a display list, it would keep the viewer's
// camera of the frame it was compiled in.
bool definitionsSetTheCamera(const Program &program) {
  const auto setsCamera = [](const Statement &statement) {
    return std::visit(
        [](const auto &body) {
          using T = std::decay_t<decltype(body)>;
          return std::is_same_v<T, Perspective> || std::is_same_v<T, Frustum> || std::is_same_v<T, Ortho> ||
                 std::is_same_v<T, LookAt>;
        },
        statement.body);
  };
  for (const Definition &definition : program.definitions)
    for (const Statement &statement : definition.body)
      if (setsCamera(statement)) return true;
  return false;
}

// What the kept context was made for (its size), and its textures and display lists (the size,
// the view and the parameter values: any other makes them again).
struct FrameKey {
  int width = 0, height = 0;
  View view = View::Color;
  std::vector<std::vector<double>> values;
  bool operator==(const FrameKey &) const = default;
};

// Deletes the texture objects and display lists an earlier frame made in the current context,
// which is to make them anew.
void forgetResources(FrameResources &resources, const Program &program) {
  if (!resources.textures.empty())
    glDeleteTextures(static_cast<GLsizei>(resources.textures.size()), resources.textures.data());
  if (resources.listBase != 0) glDeleteLists(resources.listBase, static_cast<GLsizei>(program.definitions.size()));
  resources = FrameResources{};
}

// Releases the context current on this thread when the frame is over.
struct ReleaseCurrent {
  ~ReleaseCurrent() { glassMakeCurrent(nullptr); }
};

} // namespace

struct FrameRenderer::Kept {
  GlassContext *context = nullptr;
  FrameResources resources;
  FrameKey key;
  ~Kept() { glassDestroyContext(context); }
};

FrameRenderer::FrameRenderer(const Program &program)
    : program_(program), definitionsSetCamera_(definitionsSetTheCamera(program)) {}

FrameRenderer::~FrameRenderer() = default;

bool renderFrame(const Program &program, int frame, const RenderOptions &options, RenderedFrame &result,
                 Diagnostics &diagnostics) {
  FrameRenderer renderer(program);
  return renderer.render(frame, options, result, diagnostics);
}

bool FrameRenderer::render(int frame, const RenderOptions &options, RenderedFrame &result, Diagnostics &diagnostics) {
  // Until this frame has been drawn whole, nothing is kept for the next.
  std::unique_ptr<Kept> drawing = std::move(kept_);
  const Program &program = program_;
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
  // The vertex trace needs every vertex sent (definitions not compiled), and a definition that
  // sets the camera would keep an old one: such frames make their textures and lists anew.
  const bool keepable = options.traceVertex < 0 && !definitionsSetCamera_;
  const FrameValues values = evaluateParameters(program, frame);
  FrameKey key{w, h, options.view, values.values};
  // A context of the frame's size is kept (and reset); its textures and lists too when the frame
  // would make them the same.
  bool keepResources = false;
  if (drawing && drawing->key.width == w && drawing->key.height == h && glassResetContext(drawing->context)) {
    keepResources = keepable && drawing->key == key && drawing->resources.made;
  } else {
    drawing.reset();
    auto fresh = std::make_unique<Kept>();
    fresh->context = glassCreateContext(w, h);
    if (fresh->context == nullptr) {
      diagnostics.error({}, "cannot create a " + std::to_string(w) + "x" + std::to_string(h) + " GL context");
      return false;
    }
    drawing = std::move(fresh);
  }
  drawing->key = std::move(key);
  ReleaseCurrent release;
  if (glassMakeCurrent(drawing->context) == 0) {
    diagnostics.error({}, "cannot make the " + std::to_string(w) + "x" + std::to_string(h) + " GL context current");
    return false;
  }
  if (keepResources) {
    ++framesKept_;
  } else {
    forgetResources(drawing->resources, program);
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
  interpreterOptions.camera = options.camera;
  interpreterOptions.sceneCamera = options.sceneCamera;
  interpreterOptions.resources = &drawing->resources;
  Interpreter interpreter(program, interpreterOptions);
  if (!interpreter.drawFrame(values, diagnostics)) return false;

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
  kept_ = std::move(drawing);
  return true;
}

} // namespace glass::scene
