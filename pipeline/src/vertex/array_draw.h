// glDrawArrays and glDrawElements (spec 2.8): by definition, glBegin(mode), glArrayElement for
// each index, glEnd. Inside a display list the array data is read at compile time and stored
// (CompiledArrayDraw).
#pragma once

#include <GL/gl.h>

#include <vector>

#include "texture/texture_units.h"
#include "vertex/vertex_arrays.h"

namespace glass::gl {

struct Context;

// Which arrays an element reads: the enabled ones with a pointer.
struct ArrayElementLayout {
  bool edgeFlag = false, normal = false, color = false, vertex = false;
  bool texCoord[kTextureUnitCount] = {};  // per texture unit
  bool fogCoord = false, secondaryColor = false;
};

// The values of one array element, as floats (colours and normals normalized).
struct ArrayElementValues {
  float vertex[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float color[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float normal[3] = {0.0f, 0.0f, 1.0f};
  float texCoord[kTextureUnitCount][4] = {};  // read for the units whose array is enabled
  bool edgeFlag = true;
  float fogCoord = 0.0f;
  float secondaryColor[3] = {0.0f, 0.0f, 0.0f};
};

// A glDrawArrays or glDrawElements compiled into a display list: the values readElement read of
// each element, packed per attribute the layout reads (floats, `components` per element; the edge
// flags as bytes), so that a list holds only the attributes its draws use.
struct CompiledArrayDraw {
  GLenum mode = GL_POINTS;
  ArrayElementLayout layout;
  int count = 0;  // elements
  std::vector<float> vertex, color, normal, fogCoord, secondaryColor;
  std::vector<float> texCoord[kTextureUnitCount];
  std::vector<unsigned char> edgeFlag;
};

ArrayElementLayout currentElementLayout(const ArrayState& arrays);
void readElement(const ArrayState& arrays, const ArrayElementLayout& layout, int index,
                 ArrayElementValues& out);
// Sets the current attributes of the element, then issues its vertex (spec 2.8's order).
void applyElement(Context& ctx, const ArrayElementLayout& layout, const ArrayElementValues& values);

// Draws elements first .. first + count - 1, or indices[0 .. count) when indices is not null.
// The caller checked the errors of glDrawArrays / glDrawElements.
void drawArrayElements(Context& ctx, GLenum mode, const int* indices, int first, int count);

}  // namespace glass::gl
