// Lighting state (OpenGL 1.5 specification, section 2.13 and table 6.11): the light sources, the
// front and back materials, the light model and colour material. Member initialisers are the GL
// defaults of table 2.10, so a default-constructed LightingState is the state of a new context.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

// GL_MAX_LIGHTS: the specification asks for at least 8.
inline constexpr int kMaxLights = 8;

// One light source. Positions and directions are stored in eye coordinates: glLight transforms
// them by the modelview matrix current at the time of the call (spec 2.13.2), and glGetLight
// returns them as stored.
struct LightSource {
  float ambient[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float diffuse[4] = {0.0f, 0.0f, 0.0f, 1.0f};   // GL_LIGHT0: (1, 1, 1, 1)
  float specular[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // GL_LIGHT0: (1, 1, 1, 1)
  float position[4] = {0.0f, 0.0f, 1.0f, 0.0f};  // w = 0: directional, else positional
  float spotDirection[3] = {0.0f, 0.0f, -1.0f};
  float spotExponent = 0.0f;    // [0, 128]
  float spotCutoff = 180.0f;    // [0, 90] or 180 (no spotlight)
  float constantAttenuation = 1.0f;
  float linearAttenuation = 0.0f;
  float quadraticAttenuation = 0.0f;
  bool enabled = false;         // glEnable(GL_LIGHTi)
};

// The material of one face (spec 2.13.2, table 2.10).
struct Material {
  float ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  float diffuse[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  float specular[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float emission[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;       // [0, 128]
  // GL_COLOR_INDEXES: kept for glGetMaterial; glass has no colour index mode.
  float colorIndexes[3] = {0.0f, 1.0f, 1.0f};
};

// glLightModel.
struct LightModel {
  float ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  bool localViewer = false;       // GL_LIGHT_MODEL_LOCAL_VIEWER
  bool twoSide = false;           // GL_LIGHT_MODEL_TWO_SIDE
  bool separateSpecular = false;  // GL_LIGHT_MODEL_COLOR_CONTROL == GL_SEPARATE_SPECULAR_COLOR
};

// glColorMaterial (spec 2.13.3).
struct ColorMaterialState {
  bool enabled = false;           // glEnable(GL_COLOR_MATERIAL)
  GLenum face = GL_FRONT_AND_BACK;
  GLenum mode = GL_AMBIENT_AND_DIFFUSE;
};

inline constexpr int kFrontMaterial = 0;
inline constexpr int kBackMaterial = 1;

struct LightingState {
  bool enabled = false;           // glEnable(GL_LIGHTING)
  LightSource lights[kMaxLights];
  Material materials[2];          // [kFrontMaterial], [kBackMaterial]
  LightModel model;
  ColorMaterialState colorMaterial;

  LightingState() {
    for (int c = 0; c < 4; ++c) {
      lights[0].diffuse[c] = 1.0f;
      lights[0].specular[c] = 1.0f;
    }
  }
};

}  // namespace glass::gl
