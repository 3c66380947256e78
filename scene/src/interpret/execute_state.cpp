// Vertex attributes and GL state statements.
#include "interpret/executor.h"

namespace glass::scene {

void Interpreter::Executor::run(const Color &s) {
  std::vector<double> c = values(s.rgba);
  glColor4d(c[0], c[1], c[2], c[3]);
  if (options_.tracer != nullptr) options_.tracer->setColor(c.data());
}

void Interpreter::Executor::run(const Normal &s) {
  std::vector<double> n = values(s.xyz);
  glNormal3d(n[0], n[1], n[2]);
  if (options_.tracer != nullptr) options_.tracer->setNormal(n.data());
}

void Interpreter::Executor::run(const TexCoord &s) {
  std::vector<double> t = values(s.stqr);
  switch (t.size()) {
  case 1: glTexCoord1d(t[0]); break;
  case 2: glTexCoord2d(t[0], t[1]); break;
  case 3: glTexCoord3d(t[0], t[1], t[2]); break;
  default: glTexCoord4d(t[0], t[1], t[2], t[3]); break;
  }
}

void Interpreter::Executor::run(const Vertex &s) {
  std::vector<double> v = values(s.xyzw);
  double xyzw[4] = {v[0], v[1], v.size() > 2 ? v[2] : 0.0, v.size() > 3 ? v[3] : 1.0};
  switch (v.size()) {
  case 2: glVertex2d(xyzw[0], xyzw[1]); break;
  case 3: glVertex3d(xyzw[0], xyzw[1], xyzw[2]); break;
  default: glVertex4d(xyzw[0], xyzw[1], xyzw[2], xyzw[3]); break;
  }
  if (options_.tracer != nullptr) options_.tracer->vertex(xyzw, current_->where, "'vertex'");
}

void Interpreter::Executor::run(const EdgeFlag &s) { glEdgeFlag(s.flag ? GL_TRUE : GL_FALSE); }

void Interpreter::Executor::run(const Enable &s) {
  for (GLenumValue cap : s.caps) {
    // The overdraw view owns the stencil test.
    if (options_.countOverdraw && cap == GL_STENCIL_TEST) continue;
    if (s.enable) {
      glEnable(cap);
    } else {
      glDisable(cap);
    }
  }
}

void Interpreter::Executor::run(const ShadeModel &s) {
  glShadeModel(s.mode);
  if (s.mode != GL_PHONG_WIN) return;
  // Per-pixel Phong shading is glass's GL_WIN_phong_shading extension. A GL without it rejects
  // the value (GL_INVALID_ENUM); the scene then falls back to smooth (Gouraud) shading.
  GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  if (error != GL_INVALID_ENUM) fail("the GL reported an error from glShadeModel(GL_PHONG_WIN)");
  glShadeModel(GL_SMOOTH);
  if (!phongWarned_) {
    phongWarned_ = true;
    diagnostics_.warning(current_->where,
                         "this GL has no per-pixel Phong shading (GL_WIN_phong_shading); using smooth shading",
                         current_->length);
  }
}

void Interpreter::Executor::run(const Light &s) {
  GLenum light = GL_LIGHT0 + static_cast<GLenum>(s.index);
  for (const NamedValues &entry : s.values) {
    std::vector<float> v = floats(entry.values);
    if (v.size() == 1) {
      glLightf(light, entry.pname, v[0]);
    } else {
      glLightfv(light, entry.pname, v.data());
    }
  }
}

void Interpreter::Executor::run(const LightModel &s) {
  for (const NamedValues &entry : s.values) {
    if (entry.pname == GL_LIGHT_MODEL_AMBIENT) {
      std::vector<float> v = floats(entry.values);
      glLightModelfv(entry.pname, v.data());
    } else {
      glLightModeli(entry.pname, static_cast<GLint>(value(entry.values[0])));
    }
  }
}

void Interpreter::Executor::run(const Material &s) {
  for (const NamedValues &entry : s.values) {
    std::vector<float> v = floats(entry.values);
    if (entry.pname == GL_SHININESS) {
      if (v[0] < 0.0f || v[0] > 128.0f) fail("shininess must be between 0 and 128");
      glMaterialf(s.face, entry.pname, v[0]);
    } else {
      glMaterialfv(s.face, entry.pname, v.data());
    }
    if (options_.tracer != nullptr) {
      options_.tracer->setMaterial(s.face, entry.pname, v.data(), static_cast<int>(v.size()));
    }
  }
}

void Interpreter::Executor::run(const ColorMaterial &s) { glColorMaterial(s.face, s.mode); }

void Interpreter::Executor::run(const Fog &s) {
  for (const NamedValues &entry : s.values) {
    if (entry.pname == GL_FOG_MODE) {
      glFogi(GL_FOG_MODE, static_cast<GLint>(value(entry.values[0])));
    } else if (entry.pname == GL_FOG_COLOR) {
      std::vector<float> v = floats(entry.values);
      glFogfv(GL_FOG_COLOR, v.data());
    } else {
      glFogf(entry.pname, static_cast<GLfloat>(value(entry.values[0])));
    }
  }
}

void Interpreter::Executor::run(const BlendFunc &s) { glBlendFunc(s.source, s.destination); }

void Interpreter::Executor::run(const AlphaFunc &s) {
  glAlphaFunc(s.function, static_cast<GLclampf>(value(s.reference)));
}

void Interpreter::Executor::run(const DepthFunc &s) { glDepthFunc(s.function); }

void Interpreter::Executor::run(const DepthMask &s) { glDepthMask(s.write ? GL_TRUE : GL_FALSE); }

void Interpreter::Executor::run(const DepthRange &s) { glDepthRange(value(s.zNear), value(s.zFar)); }

void Interpreter::Executor::run(const ColorMask &s) {
  glColorMask(s.rgba[0] ? GL_TRUE : GL_FALSE, s.rgba[1] ? GL_TRUE : GL_FALSE, s.rgba[2] ? GL_TRUE : GL_FALSE,
              s.rgba[3] ? GL_TRUE : GL_FALSE);
}

// The overdraw view owns the stencil buffer: the scene's stencil statements are skipped there.
void Interpreter::Executor::run(const StencilFunc &s) {
  if (!options_.countOverdraw) glStencilFunc(s.function, s.reference, s.mask);
}

void Interpreter::Executor::run(const StencilOp &s) {
  if (!options_.countOverdraw) glStencilOp(s.fail, s.depthFail, s.depthPass);
}

void Interpreter::Executor::run(const StencilMask &s) {
  if (!options_.countOverdraw) glStencilMask(s.mask);
}

void Interpreter::Executor::run(const CullFace &s) { glCullFace(s.face); }

void Interpreter::Executor::run(const FrontFace &s) { glFrontFace(s.winding); }

void Interpreter::Executor::run(const PolygonMode &s) {
  // The wireframe view keeps every polygon in line mode.
  if (!options_.wireframe) glPolygonMode(s.face, s.mode);
}

void Interpreter::Executor::run(const PolygonOffset &s) {
  glPolygonOffset(static_cast<GLfloat>(value(s.factor)), static_cast<GLfloat>(value(s.units)));
}

void Interpreter::Executor::run(const ClipPlane &s) {
  std::vector<double> e = values(s.equation);
  glClipPlane(GL_CLIP_PLANE0 + static_cast<GLenum>(s.index), e.data());
}

void Interpreter::Executor::run(const LineWidth &s) {
  double width = value(s.width);
  if (!(width > 0.0)) fail("the line width must be greater than 0");
  glLineWidth(static_cast<GLfloat>(width * widthScale()));
}

void Interpreter::Executor::run(const PointSize &s) {
  double size = value(s.size);
  if (!(size > 0.0)) fail("the point size must be greater than 0");
  glPointSize(static_cast<GLfloat>(size * widthScale()));
}

void Interpreter::Executor::run(const Scissor &s) {
  std::vector<double> v = values(s.rect);
  if (v[2] < 0 || v[3] < 0) fail("the scissor box's width and height must not be negative");
  glScissor(scaledX(v[0]), scaledY(v[1]), scaledX(v[2]), scaledY(v[3]));
}

void Interpreter::Executor::run(const LogicOp &s) { glLogicOp(s.op); }

void Interpreter::Executor::run(const BindTexture &s) {
  glBindTexture(GL_TEXTURE_2D, s.texture < 0 ? 0 : textures_[static_cast<std::size_t>(s.texture)]);
}

void Interpreter::Executor::run(const TexEnv &s) {
  if (s.mode) glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(*s.mode));
  if (!s.color.empty()) {
    std::vector<float> c = floats(s.color);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c.data());
  }
}

void Interpreter::Executor::run(const TexGen &s) {
  if (s.mode) glTexGeni(s.coord, GL_TEXTURE_GEN_MODE, static_cast<GLint>(*s.mode));
  if (!s.objectPlane.empty()) {
    std::vector<double> p = values(s.objectPlane);
    glTexGendv(s.coord, GL_OBJECT_PLANE, p.data());
  }
  if (!s.eyePlane.empty()) {
    std::vector<double> p = values(s.eyePlane);
    glTexGendv(s.coord, GL_EYE_PLANE, p.data());
  }
}

} // namespace glass::scene
