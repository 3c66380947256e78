// Client vertex arrays (spec 2.8; table 6.6): glVertexPointer and friends, and their enables.
// Pointers are the application's; glass reads them only while drawing (or, for a display list
// being compiled, while compiling: spec 5.4 says array data is dereferenced at compile time).
#pragma once

#include <GL/gl.h>

#include "texture/texture_units.h"

namespace glass::gl {

struct ClientArray {
  bool enabled = false;
  int size = 4;             // components per element
  GLenum type = GL_FLOAT;
  int stride = 0;           // as given; 0 means tightly packed
  const void* pointer = nullptr;
};

struct ArrayState {
  ClientArray vertex;                         // size 4, GL_FLOAT
  ClientArray color;                          // size 4, GL_FLOAT
  ClientArray normal{false, 3, GL_FLOAT, 0, nullptr};
  ClientArray texCoord[kTextureUnitCount];    // size 4, GL_FLOAT, one per texture unit
  int clientActiveUnit = 0;  // glClientActiveTexture: the unit of glTexCoordPointer (spec 2.8)
  ClientArray edgeFlag{false, 1, GL_UNSIGNED_BYTE, 0, nullptr};
  ClientArray index{false, 1, GL_FLOAT, 0, nullptr};  // glIndexPointer: never read in RGBA mode
  ClientArray fogCoord{false, 1, GL_FLOAT, 0, nullptr};        // glFogCoordPointer (1.4)
  ClientArray secondaryColor{false, 3, GL_FLOAT, 0, nullptr};  // glSecondaryColorPointer (1.4)
};

struct Context;

// glArrayElement(i): the enabled arrays' elements i, sent as glEdgeFlag, glMultiTexCoord for each
// unit, glNormal,
// glColor and, last, glVertex (spec 2.8). When a display list is being compiled, the values are
// read now and compiled as those commands.
void arrayElement(Context& ctx, int index);

// Bytes per component of an array type, 0 for a type arrays do not accept.
int arrayTypeBytes(GLenum type);
// Bytes from one element of the array to the next: the stride given, or the element's size.
int arrayElementStride(const ClientArray& a);

}  // namespace glass::gl
