// Render modes (OpenGL 1.5 specification, sections 5.2 and 5.3; table 6.31): glRenderMode's
// current mode, the selection buffer and name stack, and the feedback buffer.
//
// The buffers are the application's: glSelectBuffer and glFeedbackBuffer hand glass a pointer
// that it writes while the mode is on, never past the size given.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

// GL_MAX_NAME_STACK_DEPTH (the specification asks for at least 64), as in Mesa.
inline constexpr int kMaxNameStackDepth = 64;

struct SelectionState {
  GLuint* buffer = nullptr;
  int bufferSize = 0;
  bool bufferGiven = false;      // glSelectBuffer was called: glRenderMode(GL_SELECT) needs it
  long long written = 0;         // values the hit records needed, may exceed bufferSize
  int hits = 0;

  GLuint nameStack[kMaxNameStackDepth] = {};
  int nameStackDepth = 0;

  // The hit being collected since the last name stack change (spec 5.2): a primitive or raster
  // position that survived clipping sets the flag and widens the depth range, in [0, 1].
  bool hitFlag = false;
  float hitMinDepth = 1.0f;
  float hitMaxDepth = 0.0f;
};

struct FeedbackState {
  GLfloat* buffer = nullptr;
  int bufferSize = 0;
  bool bufferGiven = false;      // glFeedbackBuffer was called
  GLenum type = GL_2D;           // GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE
  long long written = 0;         // values feedback produced, may exceed bufferSize
};

struct RenderModeState {
  GLenum mode = GL_RENDER;       // GL_RENDER, GL_SELECT or GL_FEEDBACK
  SelectionState selection;
  FeedbackState feedback;
};

}  // namespace glass::gl
