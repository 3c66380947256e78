// Shadow mapping with GL 1.4's depth textures (ARB_depth_texture, ARB_shadow), in the classic
// two steps: `shadow_map` draws the casters' depth as the light sees them and copies it into a
// depth texture; `shadow_texgen` binds that texture and generates, for every vertex, its position
// in the light's clip space scaled to [0, 1] (eye-linear texture coordinate generation whose
// planes are the rows of bias x projection x view, OpenGL 1.4 section 2.11.4), so that the
// texture compares r, the vertex's depth from the light, with the depth stored there
// (section 3.8.14). docs/scene-format.md gives the GL calls.
#include <algorithm>
#include <cmath>

#include "interpret/executor.h"

namespace glass::scene {

namespace {

// What is wrong with a light's perspective, or null (gluPerspective's own conditions).
const char *lightViewProblem(double fovy, double zNear, double zFar) {
  if (!(fovy > 0.0 && fovy < 180.0)) return "the light's field of view must be between 0 and 180 degrees";
  if (!(zNear > 0.0 && zFar > zNear)) return "the light's view needs 0 < near < far";
  return nullptr;
}

} // namespace

int Interpreter::Executor::shadowMapSize(const TextureDefinition &texture) const {
  const int frameWidth = scaledX(program_.width), frameHeight = scaledY(program_.height);
  return std::max(1, std::min({texture.depthSize, frameWidth, frameHeight}));
}

void Interpreter::Executor::makeDepthTexture(const TextureDefinition &texture) {
  const int size = shadowMapSize(texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(texture.compareFunction));
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, static_cast<GLint>(texture.depthTextureMode));
}

void Interpreter::Executor::lightTextureMatrix(const LightView &light, GLdouble m[16]) {
  const std::vector<double> from = values(light.from), to = values(light.to), up = values(light.up);
  const double fovy = value(light.fovy), zNear = value(light.zNear), zFar = value(light.zFar);
  if (const char *problem = lightViewProblem(fovy, zNear, zFar)) fail(problem);
  GLint mode = GL_MODELVIEW;
  glGetIntegerv(GL_MATRIX_MODE, &mode);
  glMatrixMode(GL_TEXTURE);
  glPushMatrix();
  glLoadIdentity();
  glTranslated(0.5, 0.5, 0.5);  // [-1, 1] -> [0, 1]
  glScaled(0.5, 0.5, 0.5);
  gluPerspective(fovy, 1.0, zNear, zFar);
  gluLookAt(from[0], from[1], from[2], to[0], to[1], to[2], up[0], up[1], up[2]);
  glGetDoublev(GL_TEXTURE_MATRIX, m);
  glPopMatrix();
  glMatrixMode(static_cast<GLenum>(mode));
}

void Interpreter::Executor::run(const ShadowMap &s) {
  const TextureDefinition &texture = program_.textures[static_cast<std::size_t>(s.texture)];
  const int size = shadowMapSize(texture);
  const std::vector<double> from = values(s.light.from), to = values(s.light.to), up = values(s.light.up);
  const double fovy = value(s.light.fovy), zNear = value(s.light.zNear), zFar = value(s.light.zFar);
  if (const char *problem = lightViewProblem(fovy, zNear, zFar)) fail(problem);

  glPushAttrib(GL_VIEWPORT_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_ENABLE_BIT | GL_POLYGON_BIT |
               GL_SCISSOR_BIT | GL_TEXTURE_BIT | GL_TRANSFORM_BIT);
  glViewport(0, 0, size, size);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  gluPerspective(fovy, 1.0, zNear, zFar);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  gluLookAt(from[0], from[1], from[2], to[0], to[1], to[2], up[0], up[1], up[2]);
  // Depth only: no colour, no lighting or texturing to compute, every face (a caster's back
  // faces cast shadows too), pushed back by the polygon offset so that lit surfaces do not
  // shadow themselves.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(static_cast<GLfloat>(value(s.offsetFactor)), static_cast<GLfloat>(value(s.offsetUnits)));
  glClear(GL_DEPTH_BUFFER_BIT);
  run(Instance{s.definition});
  glBindTexture(GL_TEXTURE_2D, textures_[static_cast<std::size_t>(s.texture)]);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, size, size);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glPopAttrib();  // restores the matrix mode, the binding, the masks and the enables
  // The camera's drawing starts from a clear depth buffer, as after the frame's own clear.
  glClear(GL_DEPTH_BUFFER_BIT);
}

void Interpreter::Executor::run(const ShadowTexGen &s) {
  GLdouble m[16];
  lightTextureMatrix(s.light, m);
  // Row i of the column-major matrix is the plane of coordinate i; given with the camera's
  // modelview current, the planes are in world space (spec 2.11.4: multiplied by its inverse).
  const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  const GLenum enables[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
  for (int i = 0; i < 4; ++i) {
    const GLdouble plane[4] = {m[i], m[4 + i], m[8 + i], m[12 + i]};
    glTexGeni(coords[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGendv(coords[i], GL_EYE_PLANE, plane);
    glEnable(enables[i]);
  }
  glBindTexture(GL_TEXTURE_2D, textures_[static_cast<std::size_t>(s.texture)]);
  glEnable(GL_TEXTURE_2D);
}

} // namespace glass::scene
