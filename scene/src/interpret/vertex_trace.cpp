#include "interpret/vertex_trace.h"

#include "gl_api.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include "glass/geometry/portable_math.h"

namespace glass::scene {

namespace {

using Vec4 = std::array<double, 4>;
using Vec3 = std::array<double, 3>;

// m * v for a column-major 4x4 matrix as glGet returns it.
Vec4 transform(const std::array<double, 16> &m, const Vec4 &v) {
  Vec4 out{};
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out[static_cast<std::size_t>(r)] += m[static_cast<std::size_t>(c * 4 + r)] * v[static_cast<std::size_t>(c)];
  }
  return out;
}

double dot3(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized3(const Vec3 &v) {
  double length = std::sqrt(dot3(v, v));
  return length > 0.0 ? Vec3{v[0] / length, v[1] / length, v[2] / length} : v;
}

// The normal matrix: the inverse transpose of the modelview matrix's upper 3x3 (OpenGL 1.1
// section 2.10.3: normals transform as n' = n M^-1, a row vector).
Vec3 transformNormal(const std::array<double, 16> &m, const Vec3 &n) {
  auto a = [&](int r, int c) { return m[static_cast<std::size_t>(c * 4 + r)]; };
  double c00 = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1);
  double c01 = a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2);
  double c02 = a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0);
  double c10 = a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2);
  double c11 = a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0);
  double c12 = a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1);
  double c20 = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1);
  double c21 = a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2);
  double c22 = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  double det = a(0, 0) * c00 + a(0, 1) * c01 + a(0, 2) * c02;
  if (det == 0.0) return n;
  // (M^-1)^T = cofactor matrix / det.
  return {(c00 * n[0] + c01 * n[1] + c02 * n[2]) / det, (c10 * n[0] + c11 * n[1] + c12 * n[2]) / det,
          (c20 * n[0] + c21 * n[1] + c22 * n[2]) / det};
}

std::string format4(const Vec4 &v) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "(%11.6f, %11.6f, %11.6f, %11.6f)", v[0], v[1], v[2], v[3]);
  return buffer;
}

std::string format3(double x, double y, double z) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "(%11.6f, %11.6f, %11.6f)", x, y, z);
  return buffer;
}

Vec4 getLight4(GLenum light, GLenum pname) {
  GLfloat v[4] = {0, 0, 0, 0};
  glGetLightfv(light, pname, v);
  return {v[0], v[1], v[2], v[3]};
}

double getLight1(GLenum light, GLenum pname) {
  GLfloat v[4] = {0, 0, 0, 0};
  glGetLightfv(light, pname, v);
  return v[0];
}

Vec4 getMaterial4(GLenum face, GLenum pname) {
  GLfloat v[4] = {0, 0, 0, 0};
  glGetMaterialfv(face, pname, v);
  return {v[0], v[1], v[2], v[3]};
}

} // namespace

void VertexTracer::capture() {
  if (found_) return;
  captured_ = true;
  glGetDoublev(GL_MODELVIEW_MATRIX, modelview_.data());
  glGetDoublev(GL_PROJECTION_MATRIX, projection_.data());
  glGetDoublev(GL_VIEWPORT, viewport_.data());
  glGetDoublev(GL_DEPTH_RANGE, depthRange_.data());
  GLdouble current[4] = {1, 1, 1, 1};
  glGetDoublev(GL_CURRENT_COLOR, current);
  color_ = {current[0], current[1], current[2], current[3]};
  glGetDoublev(GL_CURRENT_NORMAL, current);
  normal_ = {current[0], current[1], current[2]};
  lighting_ = glIsEnabled(GL_LIGHTING) == GL_TRUE;
  if (!lighting_) return;
  normalize_ = glIsEnabled(GL_NORMALIZE) == GL_TRUE || glIsEnabled(GL_RESCALE_NORMAL) == GL_TRUE;
  colorMaterial_ = glIsEnabled(GL_COLOR_MATERIAL) == GL_TRUE;
  GLint value = 0;
  glGetIntegerv(GL_COLOR_MATERIAL_FACE, &value);
  colorMaterialFace_ = static_cast<unsigned>(value);
  glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &value);
  colorMaterialMode_ = static_cast<unsigned>(value);
  GLboolean flag = GL_FALSE;
  glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &flag);
  twoSide_ = flag == GL_TRUE;
  glGetBooleanv(GL_LIGHT_MODEL_LOCAL_VIEWER, &flag);
  localViewer_ = flag == GL_TRUE;
  GLfloat ambient[4] = {0, 0, 0, 0};
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, ambient);
  sceneAmbient_ = {ambient[0], ambient[1], ambient[2], ambient[3]};
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    GLenum id = GL_LIGHT0 + static_cast<GLenum>(i);
    Light &light = lights_[i];
    light.enabled = glIsEnabled(id) == GL_TRUE;
    if (!light.enabled) continue;
    light.ambient = getLight4(id, GL_AMBIENT);
    light.diffuse = getLight4(id, GL_DIFFUSE);
    light.specular = getLight4(id, GL_SPECULAR);
    light.position = getLight4(id, GL_POSITION); // stored in eye coordinates
    Vec4 direction = getLight4(id, GL_SPOT_DIRECTION);
    light.spotDirection = {direction[0], direction[1], direction[2]};
    light.spotExponent = getLight1(id, GL_SPOT_EXPONENT);
    light.spotCutoff = getLight1(id, GL_SPOT_CUTOFF);
    light.constant = getLight1(id, GL_CONSTANT_ATTENUATION);
    light.linear = getLight1(id, GL_LINEAR_ATTENUATION);
    light.quadratic = getLight1(id, GL_QUADRATIC_ATTENUATION);
  }
  for (int side = 0; side < 2; ++side) {
    GLenum face = side == 0 ? GL_FRONT : GL_BACK;
    MaterialState &m = side == 0 ? front_ : back_;
    m.ambient = getMaterial4(face, GL_AMBIENT);
    m.diffuse = getMaterial4(face, GL_DIFFUSE);
    m.specular = getMaterial4(face, GL_SPECULAR);
    m.emission = getMaterial4(face, GL_EMISSION);
    m.shininess = getMaterial4(face, GL_SHININESS)[0];
  }
}

void VertexTracer::setColor(const double rgba[4]) {
  color_ = {rgba[0], rgba[1], rgba[2], rgba[3]};
}

void VertexTracer::setNormal(const double xyz[3]) { normal_ = {xyz[0], xyz[1], xyz[2]}; }

void VertexTracer::setMaterial(unsigned face, unsigned pname, const float *values, int count) {
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 && face == GL_BACK) || (side == 1 && face == GL_FRONT)) continue;
    MaterialState &m = side == 0 ? front_ : back_;
    Vec4 v{values[0], count > 1 ? values[1] : 0.0, count > 2 ? values[2] : 0.0, count > 3 ? values[3] : 1.0};
    switch (pname) {
    case GL_AMBIENT: m.ambient = v; break;
    case GL_DIFFUSE: m.diffuse = v; break;
    case GL_AMBIENT_AND_DIFFUSE: m.ambient = v, m.diffuse = v; break;
    case GL_SPECULAR: m.specular = v; break;
    case GL_EMISSION: m.emission = v; break;
    case GL_SHININESS: m.shininess = values[0]; break;
    default: break;
    }
  }
}

void VertexTracer::vertex(const double xyzw[4], SourceLocation where, const std::string &what) {
  if (!found_ && count_ == target_) {
    describe({xyzw[0], xyzw[1], xyzw[2], xyzw[3]}, where, what);
    found_ = true;
  }
  ++count_;
}

// The lighting equation of OpenGL 1.1, section 2.13.1:
//   c = e + a_m a_scene + sum_i att_i spot_i [a_m a_i + max(n.L, 0) d_m d_i + f_i max(n.h, 0)^s s_m s_i]
std::array<double, 4> VertexTracer::litColor(const Vec4 &eye, const Vec3 &n, bool back) const {
  MaterialState m = back ? back_ : front_;
  if (colorMaterial_) {
    bool applies = colorMaterialFace_ == GL_FRONT_AND_BACK || (colorMaterialFace_ == GL_FRONT) == !back;
    if (applies) {
      switch (colorMaterialMode_) {
      case GL_AMBIENT: m.ambient = color_; break;
      case GL_DIFFUSE: m.diffuse = color_; break;
      case GL_SPECULAR: m.specular = color_; break;
      case GL_EMISSION: m.emission = color_; break;
      default: m.ambient = color_, m.diffuse = color_; break;
      }
    }
  }
  Vec3 v{eye[0] / eye[3], eye[1] / eye[3], eye[2] / eye[3]};
  Vec4 c{};
  for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(k)] = m.emission[static_cast<std::size_t>(k)] + m.ambient[static_cast<std::size_t>(k)] * sceneAmbient_[static_cast<std::size_t>(k)];
  for (const Light &light : lights_) {
    if (!light.enabled) continue;
    Vec3 toLight;
    double attenuation = 1.0;
    if (light.position[3] != 0.0) {
      Vec3 p{light.position[0] / light.position[3], light.position[1] / light.position[3],
             light.position[2] / light.position[3]};
      Vec3 d{p[0] - v[0], p[1] - v[1], p[2] - v[2]};
      double distance = std::sqrt(dot3(d, d));
      attenuation = 1.0 / (light.constant + light.linear * distance + light.quadratic * distance * distance);
      toLight = normalized3(d);
    } else {
      toLight = normalized3({light.position[0], light.position[1], light.position[2]});
    }
    double spot = 1.0;
    if (light.spotCutoff != 180.0) {
      Vec3 s = normalized3(light.spotDirection);
      double cosine = -dot3(toLight, s);
      spot = cosine >= portable::cos(light.spotCutoff * 3.14159265358979323846 / 180.0)
                 ? portable::pow(std::max(cosine, 0.0), light.spotExponent)
                 : 0.0;
    }
    double diffuse = std::max(dot3(n, toLight), 0.0);
    Vec3 toEye = localViewer_ ? normalized3({-v[0], -v[1], -v[2]}) : Vec3{0.0, 0.0, 1.0};
    Vec3 half = normalized3({toLight[0] + toEye[0], toLight[1] + toEye[1], toLight[2] + toEye[2]});
    double specular = dot3(n, toLight) > 0.0 ? portable::pow(std::max(dot3(n, half), 0.0), m.shininess) : 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      c[k] += attenuation * spot *
              (m.ambient[k] * light.ambient[k] + diffuse * m.diffuse[k] * light.diffuse[k] +
               specular * m.specular[k] * light.specular[k]);
    }
  }
  c[3] = m.diffuse[3];
  for (double &x : c) x = std::clamp(x, 0.0, 1.0);
  return c;
}

void VertexTracer::describe(const Vec4 &object, SourceLocation where, const std::string &what) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "vertex %ld, sent by %s", target_, what.c_str());
  out += line;
  if (where.file != nullptr) {
    out += " at " + where.file->path() + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
  }
  out += "\n";
  if (!captured_) {
    out += "  (no GL state was captured for it)\n";
    report_ = out;
    return;
  }
  Vec4 eye = transform(modelview_, object);
  Vec4 clip = transform(projection_, eye);
  out += "  object  " + format4(object) + "   as given\n";
  out += "  eye     " + format4(eye) + "   = MODELVIEW x object\n";
  out += "  clip    " + format4(clip) + "   = PROJECTION x eye\n";
  bool inside = true;
  for (int k = 0; k < 3; ++k) inside = inside && std::abs(clip[static_cast<std::size_t>(k)]) <= clip[3];
  if (clip[3] == 0.0) {
    out += "  ndc     undefined: clip w is 0 (the vertex is in the eye's plane; clipping handles it)\n";
  } else {
    double nx = clip[0] / clip[3], ny = clip[1] / clip[3], nz = clip[2] / clip[3];
    out += "  ndc     " + format3(nx, ny, nz) + "                = clip xyz / clip w\n";
    // Section 2.10.1: xw = (xd + 1) w/2 + x, yw = (yd + 1) h/2 + y, zw = zd (f - n)/2 + (n + f)/2.
    double scale = pixelScale_;
    double wx = ((nx + 1.0) * viewport_[2] / 2.0 + viewport_[0]) / scale;
    double wy = ((ny + 1.0) * viewport_[3] / 2.0 + viewport_[1]) / scale;
    double wz = nz * (depthRange_[1] - depthRange_[0]) / 2.0 + (depthRange_[0] + depthRange_[1]) / 2.0;
    out += "  window  " + format3(wx, wy, wz) +
           "                = viewport and depth range applied (y up from the bottom row)\n";
  }
  if (!inside) out += "          outside the view volume: clipping removes or cuts this vertex's primitive\n";
  if (!lighting_) {
    out += "  colour  " + format4(color_) + "   lighting off: the current colour\n";
  } else {
    Vec3 n = transformNormal(modelview_, normal_);
    if (normalize_) n = normalized3(n);
    out += "  normal  " + format3(n[0], n[1], n[2]) + "                eye space, = object normal x MODELVIEW^-1" +
           std::string(normalize_ ? ", normalized" : "") + "\n";
    out += "  colour  " + format4(litColor(eye, n, false)) + "   lit, front face (lighting equation, GL 1.1 2.13.1)\n";
    if (twoSide_) {
      out += "  back    " + format4(litColor(eye, {-n[0], -n[1], -n[2]}, true)) + "   lit, back face (two-sided lighting)\n";
    }
  }
  report_ = out;
}

} // namespace glass::scene
