// The interpreter's frame: set-up, textures, definitions, the statement loop and GL errors.
#include "interpret/executor.h"

#include <algorithm>
#include <cmath>

namespace glass::scene {

namespace {

template <class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template <class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

const char *glErrorName(GLenum error) {
  switch (error) {
  case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
  case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
  case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
  case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
  case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
  case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
  default: return "an unknown GL error";
  }
}

// The GL (or GLU, GLUT) function a statement stands for, for messages.
const char *glFunctionOf(const Statement &statement) {
  return std::visit(
      Overloaded{
          [](const Viewport &) { return "glViewport"; }, [](const ClearColor &) { return "glClearColor"; },
          [](const ClearDepth &) { return "glClearDepth"; }, [](const ClearStencil &) { return "glClearStencil"; },
          [](const Clear &) { return "glClear"; }, [](const Perspective &) { return "gluPerspective"; },
          [](const Frustum &) { return "glFrustum"; }, [](const Ortho &) { return "glOrtho"; },
          [](const LookAt &) { return "gluLookAt"; }, [](const LoadIdentity &) { return "glLoadIdentity"; },
          [](const Translate &) { return "glTranslated"; }, [](const Rotate &) { return "glRotated"; },
          [](const RotateQuaternion &) { return "glMultMatrixd"; },
          [](const RotateByParameter &) { return "glRotated"; }, [](const Scale &) { return "glScaled"; },
          [](const MultMatrix &) { return "glMultMatrixd"; },
          [](const ShadowMatrix &) { return "glMultMatrixd"; },
          [](const Push &) { return "glPushMatrix/glPushAttrib"; },
          [](const Pop &) { return "glPopAttrib/glPopMatrix"; }, [](const Color &) { return "glColor4d"; },
          [](const Normal &) { return "glNormal3d"; }, [](const TexCoord &) { return "glTexCoord"; },
          [](const Vertex &) { return "glVertex"; }, [](const EdgeFlag &) { return "glEdgeFlag"; },
          [](const Enable &e) { return e.enable ? "glEnable" : "glDisable"; },
          [](const ShadeModel &) { return "glShadeModel"; }, [](const Light &) { return "glLightfv"; },
          [](const LightModel &) { return "glLightModelfv"; }, [](const Material &) { return "glMaterialfv"; },
          [](const ColorMaterial &) { return "glColorMaterial"; }, [](const Fog &) { return "glFogfv"; },
          [](const BlendFunc &) { return "glBlendFunc"; }, [](const AlphaFunc &) { return "glAlphaFunc"; },
          [](const DepthFunc &) { return "glDepthFunc"; }, [](const DepthMask &) { return "glDepthMask"; },
          [](const DepthRange &) { return "glDepthRange"; }, [](const ColorMask &) { return "glColorMask"; },
          [](const StencilFunc &) { return "glStencilFunc"; }, [](const StencilOp &) { return "glStencilOp"; },
          [](const StencilMask &) { return "glStencilMask"; }, [](const CullFace &) { return "glCullFace"; },
          [](const FrontFace &) { return "glFrontFace"; }, [](const PolygonMode &) { return "glPolygonMode"; },
          [](const PolygonOffset &) { return "glPolygonOffset"; }, [](const ClipPlane &) { return "glClipPlane"; },
          [](const LineWidth &) { return "glLineWidth"; }, [](const PointSize &) { return "glPointSize"; },
          [](const Scissor &) { return "glScissor"; }, [](const LogicOp &) { return "glLogicOp"; },
          [](const BindTexture &) { return "glBindTexture"; }, [](const TexEnv &) { return "glTexEnv"; },
          [](const TexGen &) { return "glTexGen"; }, [](const Begin &) { return "glBegin/glEnd"; },
          [](const Rect &) { return "glRectd"; }, [](const Mesh &) { return "glDrawElements/glDrawArrays"; },
          [](const DrawModel &) { return "glDrawArrays"; }, [](const Sphere &) { return "gluSphere"; },
          [](const Cylinder &) { return "gluCylinder"; }, [](const Disk &) { return "gluDisk"; },
          [](const PartialDisk &) { return "gluPartialDisk"; }, [](const GlutShape &) { return "a GLUT shape"; },
          [](const ParametricTorus &) { return "glBegin(GL_QUAD_STRIP)"; },
          [](const BezierCurve &) { return "glMap1d/glEvalMesh1"; },
          [](const BezierPatch &) { return "glMap2d/glEvalMesh2"; },
          [](const Ifs &) { return "the ifs drawing"; }, [](const Instance &) { return "glCallList"; },
          [](const Ifs3d &) { return "the ifs3d drawing"; },
          [](const ShadowMap &) { return "the shadow map"; },
          [](const ShadowTexGen &) { return "the shadow map's glTexGen"; }},
      statement.body);
}

} // namespace

Interpreter::Interpreter(const Program &program, const InterpreterOptions &options)
    : program_(program), options_(options) {}

Interpreter::~Interpreter() = default;

bool Interpreter::drawFrame(const FrameValues &values, Diagnostics &diagnostics) {
  int errorsBefore = diagnostics.errorCount();
  try {
    Executor executor(program_, options_, values, diagnostics);
    executor.drawFrame();
  } catch (const RuntimeError &error) {
    diagnostics.error(error.where, error.message, error.length);
  }
  return diagnostics.errorCount() == errorsBefore;
}

Interpreter::Executor::Executor(const Program &program, const InterpreterOptions &options,
                                const FrameValues &values, Diagnostics &diagnostics)
    : program_(program), options_(options), values_(values), diagnostics_(diagnostics) {}

std::vector<double> Interpreter::Executor::values(const Numbers &numbers) const {
  std::vector<double> out;
  out.reserve(numbers.size());
  for (const Number &n : numbers) out.push_back(value(n));
  return out;
}

std::vector<float> Interpreter::Executor::floats(const Numbers &numbers) const {
  std::vector<float> out;
  out.reserve(numbers.size());
  for (const Number &n : numbers) out.push_back(static_cast<float>(value(n)));
  return out;
}

void Interpreter::Executor::fail(const std::string &message) const {
  RuntimeError error;
  if (current_ != nullptr) {
    error.where = current_->where;
    error.length = current_->length;
  }
  error.message = message;
  throw error;
}

GLint Interpreter::Executor::scaledX(double pixels) const {
  return static_cast<GLint>(std::lround(pixels * options_.scaleX));
}

GLint Interpreter::Executor::scaledY(double pixels) const {
  return static_cast<GLint>(std::lround(pixels * options_.scaleY));
}

double Interpreter::Executor::widthScale() const { return std::sqrt(options_.scaleX * options_.scaleY); }

void Interpreter::Executor::drawFrame() {
  setUpFrame();
  FrameResources *kept = options_.resources;
  if (kept != nullptr && kept->made) {
    textures_ = kept->textures;
    listBase_ = kept->listBase;
    remakeDepthTextures();
  } else {
    uploadTextures();
    compileDefinitions();
    if (kept != nullptr) *kept = FrameResources{true, textures_, listBase_};
  }
  execute(program_.statements);
  // Leave nothing pending: GL errors of the last statements are reported, and drawing finishes.
  glFinish();
}

void Interpreter::Executor::setUpFrame() {
  // The context is fresh, so GL's initial state holds: identity matrices, the viewport covering
  // the whole image, clear values (0, 0, 0, 0), depth 1 and stencil 0. The buffers themselves
  // start undefined in GL, so the frame begins with a clear.
  if (options_.wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  if (options_.countOverdraw) {
    // Every fragment that reaches the stencil test adds one to its pixel's count, whether the
    // depth test then passes or not (GL_INCR saturates at 255).
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFFu);
    glStencilOp(GL_INCR, GL_INCR, GL_INCR);
    glStencilMask(0xFFu);
  }
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
    fail(std::string("the GL reported ") + glErrorName(error) + " while setting up the frame");
  }
}

void Interpreter::Executor::uploadTextures() {
  if (program_.textures.empty()) return;
  textures_.assign(program_.textures.size(), 0);
  glGenTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t i = 0; i < program_.textures.size(); ++i) {
    const TextureDefinition &texture = program_.textures[i];
    glBindTexture(GL_TEXTURE_2D, textures_[i]);
    const Image &image = texture.image;
    int width = image.width, height = image.height;
    if (texture.depth) {
      width = height = shadowMapSize(texture);
      makeDepthTexture(texture);
    } else {
      // Image files start with the top row; GL's texture rows start at t = 0, the bottom.
      std::vector<std::uint8_t> rows(image.rgba.size());
      std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
      for (int y = 0; y < image.height; ++y) {
        std::copy_n(&image.rgba[static_cast<std::size_t>(image.height - 1 - y) * rowBytes], rowBytes,
                    &rows[static_cast<std::size_t>(y) * rowBytes]);
      }
      if (texture.mipmaps) {
        gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
      } else {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
      }
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(texture.minFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(texture.magFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(texture.wrapS));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(texture.wrapT));
    if (!texture.borderColor.empty()) {
      std::vector<float> border = floats(texture.borderColor);
      glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border.data());
    }
    for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
      RuntimeError failure{texture.where, 7,
                           std::string("the GL reported ") + glErrorName(error) + " while loading texture '" +
                               texture.name + "' (" + std::to_string(width) + "x" +
                               std::to_string(height) + ")"};
      throw failure;
    }
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void Interpreter::Executor::remakeDepthTextures() {
  for (std::size_t i = 0; i < program_.textures.size(); ++i) {
    if (!program_.textures[i].depth) continue;
    glBindTexture(GL_TEXTURE_2D, textures_[i]);
    makeDepthTexture(program_.textures[i]);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
}

void Interpreter::Executor::compileDefinitions() {
  if (program_.definitions.empty() || !options_.compileDefinitions) return;
  listBase_ = glGenLists(static_cast<GLsizei>(program_.definitions.size()));
  if (listBase_ == 0) fail("the GL could not make display lists for the definitions");
  for (std::size_t i = 0; i < program_.definitions.size(); ++i) {
    glNewList(listBase_ + static_cast<GLuint>(i), GL_COMPILE);
    ++compilingDefinition_;
    execute(program_.definitions[i].body);
    --compilingDefinition_;
    glEndList();
  }
}

void Interpreter::Executor::execute(const StatementList &list) {
  for (const Statement &statement : list) execute(statement);
}

void Interpreter::Executor::execute(const Statement &statement) {
  const Statement *outer = current_;
  current_ = &statement;
  std::visit([this](const auto &body) { run(body); }, statement.body);
  if (insideBegin_ == 0) checkGlErrors(statement);
  current_ = outer;
}

void Interpreter::Executor::checkGlErrors(const Statement &statement) {
  std::string names;
  for (int i = 0; i < 8; ++i) {
    GLenum error = glGetError();
    if (error == GL_NO_ERROR) break;
    if (!names.empty()) names += ", ";
    names += glErrorName(error);
  }
  if (names.empty()) return;
  RuntimeError failure{statement.where, statement.length,
                       "the GL reported " + names + " from " + glFunctionOf(statement) +
                           (compilingDefinition_ > 0 ? " (while compiling a definition)" : "")};
  throw failure;
}

void Interpreter::Executor::run(const Instance &s) {
  if (listBase_ != 0) {
    glCallList(listBase_ + static_cast<GLuint>(s.definition));
  } else {
    execute(program_.definitions[static_cast<std::size_t>(s.definition)].body);
  }
}

} // namespace glass::scene
