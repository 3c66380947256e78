// Current vertex attributes (spec 2.7; table 6.5): what glColor, glNormal, glTexCoord and
// glEdgeFlag set and every later glVertex uses.
#pragma once

#include "texture/texture_units.h"

namespace glass::gl {

struct CurrentState {
  float color[4] = {1.0f, 1.0f, 1.0f, 1.0f};   // stored as given; clamped after lighting
  float normal[3] = {0.0f, 0.0f, 1.0f};
  // Per texture unit (glMultiTexCoord; glTexCoord is unit 0), (0, 0, 0, 1) each.
  float texCoord[kTextureUnitCount][4] = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f},
                                          {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f},
                                          {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f},
                                          {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f}};
  bool edgeFlag = true;
  float index = 1.0f;  // glIndex: kept and queried, no effect in RGBA mode (core/color_index.h)
  float fogCoord = 0.0f;                                 // glFogCoord (OpenGL 1.4)
  float secondaryColor[4] = {0.0f, 0.0f, 0.0f, 1.0f};   // glSecondaryColor (OpenGL 1.4)
};

}  // namespace glass::gl
