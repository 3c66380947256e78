// The names the scene language gives GL enumerants: the GL name in lower case without the GL_
// prefix (GL_DEPTH_TEST is `depth_test`, GL_SRC_ALPHA is `src_alpha`), so that a reader can find
// the GL call in any GL book. One table per place a value may appear.
#pragma once

#include "glass/scene/program.h"

#include <span>
#include <string>
#include <string_view>

namespace glass::scene {

struct EnumName {
  std::string_view name;
  GLenumValue value;
};
using EnumTable = std::span<const EnumName>;

namespace names {
extern const EnumTable capabilities;      // glEnable / glDisable
extern const EnumTable primitiveModes;    // glBegin, mesh
extern const EnumTable shadeModels;       // flat, smooth, phong (glass extension)
extern const EnumTable faces;             // front, back, front_and_back
extern const EnumTable cullFaces;         // front, back, front_and_back
extern const EnumTable windings;          // cw, ccw
extern const EnumTable compareFunctions;  // never less equal lequal greater notequal gequal always
extern const EnumTable blendSourceFactors;
extern const EnumTable blendDestinationFactors;
extern const EnumTable stencilOps;
extern const EnumTable polygonModes;      // point, line, fill
extern const EnumTable fogModes;
extern const EnumTable colorMaterialModes;
extern const EnumTable colorControls;     // single_color, separate_specular_color
extern const EnumTable logicOps;
extern const EnumTable minFilters;
extern const EnumTable magFilters;
extern const EnumTable depthTextureModes; // luminance, intensity, alpha (GL_DEPTH_TEXTURE_MODE)
extern const EnumTable wrapModes;
extern const EnumTable texEnvModes;
extern const EnumTable texGenCoords;      // s, t, r, q
extern const EnumTable texGenModes;
extern const EnumTable quadricDrawStyles; // fill, line, silhouette, point
extern const EnumTable quadricNormals;    // none, flat, smooth
extern const EnumTable quadricOrientations; // outside, inside
extern const EnumTable curveModes;        // line, point
extern const EnumTable clearBuffers;      // color, depth, stencil (as glClear bits)
} // namespace names

// The value of `name` in `table`, or false.
bool lookupEnum(EnumTable table, std::string_view name, GLenumValue &value);
// The scene name of a value (for messages and traces); "0x1234" when not in the table.
std::string enumName(EnumTable table, GLenumValue value);
// "a, b, c or d": the names a table accepts, for messages.
std::string listNames(EnumTable table);

} // namespace glass::scene
