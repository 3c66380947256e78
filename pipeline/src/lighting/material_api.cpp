// glMaterial*, glGetMaterial* and glColorMaterial (OpenGL 1.5 specification, sections 2.13.2,
// 2.13.3 and 6.1.3). glMaterial is one of the few commands allowed between glBegin and glEnd.
#include <GL/gl.h>

#include <cmath>
#include <vector>

#include "core/context.h"
#include "core/errors.h"
#include "lighting/color_material.h"
#include "lists/command_recording.h"
#include "primitive/queued_drawing.h"
#include "vertex/gathered_vertices.h"
#include "texture/integer_colors.h"

namespace glass::gl {
namespace {

// How many values a glMaterial parameter takes; 0 for a name glMaterial does not know.
int materialParameterCount(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE: return 4;
    case GL_COLOR_INDEXES: return 3;
    case GL_SHININESS: return 1;
    default: return 0;
  }
}

bool isMaterialColor(GLenum pname) { return materialParameterCount(pname) == 4; }

void setMaterialOfFace(Material& m, GLenum pname, const float* v) {
  auto copy4 = [v](float* out) {
    for (int i = 0; i < 4; ++i) out[i] = v[i];
  };
  switch (pname) {
    case GL_AMBIENT: copy4(m.ambient); break;
    case GL_DIFFUSE: copy4(m.diffuse); break;
    case GL_SPECULAR: copy4(m.specular); break;
    case GL_EMISSION: copy4(m.emission); break;
    case GL_SHININESS: m.shininess = v[0]; break;
    case GL_COLOR_INDEXES:
      for (int i = 0; i < 3; ++i) m.colorIndexes[i] = v[i];
      break;
    default: break;
  }
}

// glMaterial with float values. Parameters that colour material is tracking keep following the
// current colour: a glMaterial call does not change them.
void setMaterial(Context& ctx, GLenum face, GLenum pname, const float* v) {
  const unsigned faces = materialFaceMask(face);
  if (faces == 0 || materialParameterCount(pname) == 0) {
    recordError(ctx, GL_INVALID_ENUM);
    return;
  }
  if (pname == GL_SHININESS && (v[0] < 0.0f || v[0] > 128.0f)) {
    recordError(ctx, GL_INVALID_VALUE);
    return;
  }
  flushGatheredVertices(ctx);  // vertices before this glMaterial are lit with the old material
  finishDrawReadingContext(ctx);  // per-fragment lighting may still need the old material
  LightingState& l = ctx.lighting;
  for (int f = 0; f < 2; ++f) {
    if (!(faces & (1u << f))) continue;
    if (pname == GL_AMBIENT_AND_DIFFUSE) {
      if (!tracksCurrentColor(l.colorMaterial, f, GL_AMBIENT)) {
        setMaterialOfFace(l.materials[f], GL_AMBIENT, v);
      }
      if (!tracksCurrentColor(l.colorMaterial, f, GL_DIFFUSE)) {
        setMaterialOfFace(l.materials[f], GL_DIFFUSE, v);
      }
    } else if (!tracksCurrentColor(l.colorMaterial, f, pname)) {
      setMaterialOfFace(l.materials[f], pname, v);
    }
  }
}

void setMaterialScalar(Context& ctx, GLenum face, GLenum pname, float value) {
  if (pname != GL_SHININESS) {
    recordError(ctx, GL_INVALID_ENUM);
    return;
  }
  setMaterial(ctx, face, pname, &value);
}

// glGetMaterial: the face must be GL_FRONT or GL_BACK.
int getMaterial(Context& ctx, GLenum face, GLenum pname, float out[4]) {
  if (rejectInsideBeginEnd(ctx)) return 0;
  const int n = materialParameterCount(pname);
  if ((face != GL_FRONT && face != GL_BACK) || n == 0 || pname == GL_AMBIENT_AND_DIFFUSE) {
    recordError(ctx, GL_INVALID_ENUM);
    return 0;
  }
  const Material& m = ctx.lighting.materials[face == GL_FRONT ? kFrontMaterial : kBackMaterial];
  const float* source = pname == GL_AMBIENT     ? m.ambient
                        : pname == GL_DIFFUSE   ? m.diffuse
                        : pname == GL_SPECULAR  ? m.specular
                        : pname == GL_EMISSION  ? m.emission
                        : pname == GL_SHININESS ? &m.shininess
                                                : m.colorIndexes;
  for (int i = 0; i < n; ++i) out[i] = source[i];
  return n;
}

void setColorMaterial(Context& ctx, GLenum face, GLenum mode) {
  if (rejectInsideBeginEnd(ctx)) return;
  const bool modeKnown = mode == GL_EMISSION || mode == GL_AMBIENT || mode == GL_DIFFUSE ||
                         mode == GL_SPECULAR || mode == GL_AMBIENT_AND_DIFFUSE;
  if (materialFaceMask(face) == 0 || !modeKnown) {
    recordError(ctx, GL_INVALID_ENUM);
    return;
  }
  ctx.lighting.colorMaterial.face = face;
  ctx.lighting.colorMaterial.mode = mode;
  // While enabled, the newly named parameters take the current colour at once.
  applyColorMaterial(ctx.lighting, ctx.current.color);
}

// Copies glMaterial's values for a display list, padded to 4.
template <class T>
std::vector<T> materialValues(GLenum pname, const T* params) {
  const int n = params ? materialParameterCount(pname) : 0;
  std::vector<T> out(params, params + n);
  out.resize(4, T(0));
  return out;
}

}  // namespace
}  // namespace glass::gl

using glass::gl::compileOrExecute;
using glass::gl::Context;

extern "C" {

void glMaterialf(GLenum face, GLenum pname, GLfloat param) {
  compileOrExecute([=](Context& ctx) { glass::gl::setMaterialScalar(ctx, face, pname, param); });
}

void glMateriali(GLenum face, GLenum pname, GLint param) {
  compileOrExecute([=](Context& ctx) {
    glass::gl::setMaterialScalar(ctx, face, pname, static_cast<float>(param));
  });
}

void glMaterialfv(GLenum face, GLenum pname, const GLfloat* params) {
  const std::vector<float> values = glass::gl::materialValues(pname, params);
  const bool known = params != nullptr && glass::gl::materialParameterCount(pname) != 0;
  compileOrExecute([=](Context& ctx) {
    if (!known) {
      glass::gl::recordError(ctx, GL_INVALID_ENUM);
      return;
    }
    glass::gl::setMaterial(ctx, face, pname, values.data());
  });
}

void glMaterialiv(GLenum face, GLenum pname, const GLint* params) {
  const std::vector<GLint> integers = glass::gl::materialValues(pname, params);
  std::vector<float> values(4);
  for (int i = 0; i < 4; ++i) {
    // Colours map the integer range onto [-1, 1] (table 2.9); shininess and indexes convert
    // directly.
    values[i] = glass::gl::isMaterialColor(pname)
                    ? static_cast<float>(glass::gl::integerToColor(integers[i]))
                    : static_cast<float>(integers[i]);
  }
  const bool known = params != nullptr && glass::gl::materialParameterCount(pname) != 0;
  compileOrExecute([=](Context& ctx) {
    if (!known) {
      glass::gl::recordError(ctx, GL_INVALID_ENUM);
      return;
    }
    glass::gl::setMaterial(ctx, face, pname, values.data());
  });
}

void glGetMaterialfv(GLenum face, GLenum pname, GLfloat* params) {
  glass::gl::executeNow([=](Context& ctx) {
    float values[4];
    const int n = glass::gl::getMaterial(ctx, face, pname, values);
    for (int i = 0; i < n && params; ++i) params[i] = values[i];
  });
}

void glGetMaterialiv(GLenum face, GLenum pname, GLint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    float values[4];
    const int n = glass::gl::getMaterial(ctx, face, pname, values);
    const bool isColor = glass::gl::isMaterialColor(pname);
    for (int i = 0; i < n && params; ++i) params[i] = glass::gl::queriedInteger(values[i], isColor);
  });
}

void glColorMaterial(GLenum face, GLenum mode) {
  compileOrExecute([=](Context& ctx) { glass::gl::setColorMaterial(ctx, face, mode); });
}

}  // extern "C"
