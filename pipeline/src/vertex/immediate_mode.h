// Immediate mode (spec 2.6, 2.7): glBegin/glEnd, glVertex and the current attributes. These are
// the commands' work on a context; the GL entry points (api/immediate_api.cpp) record or run them,
// and so do vertex arrays and display lists.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct Context;

void beginCommand(Context& ctx, GLenum mode);  // glBegin, with its errors
void endCommand(Context& ctx);                 // glEnd, with its errors

// glVertex: outside glBegin/glEnd it does nothing (the spec leaves it undefined).
void vertexCommand(Context& ctx, float x, float y, float z, float w);
void colorCommand(Context& ctx, float r, float g, float b, float a);
void normalCommand(Context& ctx, float x, float y, float z);
// glMultiTexCoord (glTexCoord for unit 0): (s, t, r, q) of texture unit `unit` (0-based).
void texCoordCommand(Context& ctx, int unit, const float coords[4]);
void edgeFlagCommand(Context& ctx, bool flag);
// OpenGL 1.4: glSecondaryColor (alpha stays 1, spec 2.7) and glFogCoord.
void secondaryColorCommand(Context& ctx, float r, float g, float b);
void fogCoordCommand(Context& ctx, float c);

// glRect: Begin(POLYGON), the four corners counter-clockwise from (x1, y1), End (spec 2.10).
void rectCommand(Context& ctx, float x1, float y1, float x2, float y2);

}  // namespace glass::gl
