// The interpreter's working part: one `run` overload per statement type, each issuing the GL
// calls of its statement (docs/scene-format.md lists them).
#pragma once

#include "gl_api.h"
#include "interpret/interpreter.h"
#include "interpret/vertex_trace.h"

#include <string>
#include <vector>

namespace glass::scene {

// A problem found while drawing: a GL error after a statement, or a parameter value the GL
// would reject. Carries the statement's place.
struct RuntimeError {
  SourceLocation where;
  int length = 1;
  std::string message;
};

class Interpreter::Executor {
public:
  Executor(const Program &program, const InterpreterOptions &options, const FrameValues &values,
           Diagnostics &diagnostics);

  // GL's initial state is assumed; sets up the frame, uploads textures, compiles definitions,
  // then runs every statement.
  void drawFrame();

  void execute(const StatementList &list);
  void execute(const Statement &statement);

  // Output and camera (execute_camera.cpp).
  void run(const Viewport &s);
  void run(const ClearColor &s);
  void run(const ClearDepth &s);
  void run(const ClearStencil &s);
  void run(const Clear &s);
  void run(const Perspective &s);
  void run(const Frustum &s);
  void run(const Ortho &s);
  void run(const LookAt &s);
  void run(const LoadIdentity &s);
  void run(const Translate &s);
  void run(const Rotate &s);
  void run(const RotateQuaternion &s);
  void run(const RotateByParameter &s);
  void run(const Scale &s);
  void run(const MultMatrix &s);
  void run(const ShadowMatrix &s);
  void run(const Push &s);
  void run(const Pop &s);

  // Attributes and state (execute_state.cpp).
  void run(const Color &s);
  void run(const Normal &s);
  void run(const TexCoord &s);
  void run(const Vertex &s);
  void run(const EdgeFlag &s);
  void run(const Enable &s);
  void run(const ShadeModel &s);
  void run(const Light &s);
  void run(const LightModel &s);
  void run(const Material &s);
  void run(const ColorMaterial &s);
  void run(const Fog &s);
  void run(const BlendFunc &s);
  void run(const AlphaFunc &s);
  void run(const DepthFunc &s);
  void run(const DepthMask &s);
  void run(const DepthRange &s);
  void run(const ColorMask &s);
  void run(const StencilFunc &s);
  void run(const StencilOp &s);
  void run(const StencilMask &s);
  void run(const CullFace &s);
  void run(const FrontFace &s);
  void run(const PolygonMode &s);
  void run(const PolygonOffset &s);
  void run(const ClipPlane &s);
  void run(const LineWidth &s);
  void run(const PointSize &s);
  void run(const Scissor &s);
  void run(const LogicOp &s);
  void run(const BindTexture &s);
  void run(const TexEnv &s);
  void run(const TexGen &s);

  // Geometry (execute_geometry.cpp, execute_shapes.cpp, execute_ifs.cpp).
  void run(const Begin &s);
  void run(const Rect &s);
  void run(const Mesh &s);
  void run(const DrawModel &s);
  void drawModelParts(const Model &model, const std::vector<ModelPart> &parts, const DrawModel &s);
  void run(const Sphere &s);
  void run(const Cylinder &s);
  void run(const Disk &s);
  void run(const PartialDisk &s);
  void run(const GlutShape &s);
  void run(const ParametricTorus &s);
  void run(const BezierCurve &s);
  void run(const BezierPatch &s);
  void run(const Ifs &s);
  void run(const Ifs3d &s);
  void run(const Instance &s);
  void run(const ShadowMap &s);    // execute_shadow_map.cpp
  void run(const ShadowTexGen &s);

  double value(const Number &n) const { return values_(n); }
  std::vector<double> values(const Numbers &numbers) const;
  std::vector<float> floats(const Numbers &numbers) const;
  // Stops the frame with a message at the current statement.
  [[noreturn]] void fail(const std::string &message) const;
  // Before a glPushAttrib and after its glPopAttrib of GL_CURRENT_BIT: the current vertex values
  // saved and sent again (execute_camera.cpp says why).
  void saveCurrentValues();
  void resendCurrentValues();

private:
  void setUpFrame();
  void uploadTextures();
  // A shadow map's texels a side: its `size`, at most the frame's width and height, since the
  // depth is drawn into the frame's depth buffer and copied from there.
  int shadowMapSize(const TextureDefinition &texture) const;
  void makeDepthTexture(const TextureDefinition &texture);
  // The shadow maps' textures of kept resources, empty again as uploadTextures leaves them.
  void remakeDepthTextures();
  // M = bias x gluPerspective(light) x gluLookAt(light), column-major, computed by the GL's own
  // matrix calls on the texture stack (which is left as it was).
  void lightTextureMatrix(const LightView &light, GLdouble m[16]);
  void compileDefinitions();
  // Reports GL errors raised by the statement just run.
  void checkGlErrors(const Statement &statement);
  GLint scaledX(double pixels) const;
  GLint scaledY(double pixels) const;
  double widthScale() const;

  const Program &program_;
  const InterpreterOptions &options_;
  const FrameValues &values_;
  Diagnostics &diagnostics_;
  const Statement *current_ = nullptr;
  int insideBegin_ = 0;
  int compilingDefinition_ = 0;
  std::vector<GLuint> textures_;
  GLuint listBase_ = 0;
  bool phongWarned_ = false;
  struct CurrentValues {
    GLdouble color[4];
    GLdouble normal[3];
    GLdouble texcoord[4];
    GLboolean edgeFlag;
  };
  std::vector<CurrentValues> savedCurrentValues_;
};

} // namespace glass::scene
