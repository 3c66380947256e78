// glAccum and the accumulation buffer's part of glClear (OpenGL 1.5 specification, section
// 4.2.4). Values are kept as Mesa keeps them (accumulation_state.h) and every operation rounds as
// Mesa's does, so that the Red Book's jittered-frustum antialiasing and depth of field come out
// the same:
//   GL_LOAD    A = trunc(C * (value * 32767))        C the colour buffer, c / 255
//   GL_ACCUM   A = A + trunc(C * (value * 32767))    (skipped for value 0)
//   GL_ADD     A = A + trunc(value * 32767)          (skipped for value 0)
//   GL_MULT    A = trunc(A * value)                  (skipped for value 1)
//   GL_RETURN  C = A * (value / 32767), clamped to [0, 1], rounded to 8 bits (ties to even),
//              written through the colour write masks; no other fragment operation applies
// Sums are saturated to the 16-bit range (the specification leaves overflow undefined). All
// operations act on the scissor box when the scissor test is on, and on the whole window
// otherwise; in selection and feedback modes glAccum does nothing.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;
struct StateValue;

bool isAccumOperation(GLenum op);

// glAccum's work once its errors are checked. Records GL_OUT_OF_MEMORY when the buffer cannot be
// allocated.
void accumulate(Context& ctx, GLenum op, float value);

// glClear(GL_ACCUM_BUFFER_BIT) within the rectangle [x0, x1) x [y0, y1): sets the accumulation
// buffer to the glClearAccum value, as Mesa stores it: (c * 65535 - 1) / 2 truncated.
void clearAccumulationBuffer(Context& ctx, int x0, int y0, int x1, int y1);

// glGet of GL_ACCUM_CLEAR_VALUE and GL_ACCUM_*_BITS. False for other names.
bool queryAccumulationState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
