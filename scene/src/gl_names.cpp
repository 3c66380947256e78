#include "gl_names.h"

#include "gl_api.h"

#include <cstdio>

namespace glass::scene {

namespace {

constexpr EnumName kCapabilities[] = {
    {"alpha_test", GL_ALPHA_TEST},
    {"auto_normal", GL_AUTO_NORMAL},
    {"blend", GL_BLEND},
    {"clip_plane0", GL_CLIP_PLANE0},
    {"clip_plane1", GL_CLIP_PLANE1},
    {"clip_plane2", GL_CLIP_PLANE2},
    {"clip_plane3", GL_CLIP_PLANE3},
    {"clip_plane4", GL_CLIP_PLANE4},
    {"clip_plane5", GL_CLIP_PLANE5},
    {"color_logic_op", GL_COLOR_LOGIC_OP},
    {"color_material", GL_COLOR_MATERIAL},
    {"cull_face", GL_CULL_FACE},
    {"depth_test", GL_DEPTH_TEST},
    {"dither", GL_DITHER},
    {"fog", GL_FOG},
    {"light0", GL_LIGHT0},
    {"light1", GL_LIGHT1},
    {"light2", GL_LIGHT2},
    {"light3", GL_LIGHT3},
    {"light4", GL_LIGHT4},
    {"light5", GL_LIGHT5},
    {"light6", GL_LIGHT6},
    {"light7", GL_LIGHT7},
    {"lighting", GL_LIGHTING},
    {"line_smooth", GL_LINE_SMOOTH},
    {"normalize", GL_NORMALIZE},
    {"point_smooth", GL_POINT_SMOOTH},
    {"polygon_offset_fill", GL_POLYGON_OFFSET_FILL},
    {"polygon_offset_line", GL_POLYGON_OFFSET_LINE},
    {"polygon_offset_point", GL_POLYGON_OFFSET_POINT},
    {"rescale_normal", GL_RESCALE_NORMAL},
    {"scissor_test", GL_SCISSOR_TEST},
    {"stencil_test", GL_STENCIL_TEST},
    {"texture_1d", GL_TEXTURE_1D},
    {"texture_2d", GL_TEXTURE_2D},
    {"texture_gen_q", GL_TEXTURE_GEN_Q},
    {"texture_gen_r", GL_TEXTURE_GEN_R},
    {"texture_gen_s", GL_TEXTURE_GEN_S},
    {"texture_gen_t", GL_TEXTURE_GEN_T},
};

constexpr EnumName kPrimitiveModes[] = {
    {"points", GL_POINTS},
    {"lines", GL_LINES},
    {"line_strip", GL_LINE_STRIP},
    {"line_loop", GL_LINE_LOOP},
    {"triangles", GL_TRIANGLES},
    {"triangle_strip", GL_TRIANGLE_STRIP},
    {"triangle_fan", GL_TRIANGLE_FAN},
    {"quads", GL_QUADS},
    {"quad_strip", GL_QUAD_STRIP},
    {"polygon", GL_POLYGON},
};

constexpr EnumName kShadeModels[] = {
    {"flat", GL_FLAT},
    {"smooth", GL_SMOOTH},
    {"phong", GL_PHONG_WIN},
};

constexpr EnumName kFaces[] = {
    {"front", GL_FRONT},
    {"back", GL_BACK},
    {"front_and_back", GL_FRONT_AND_BACK},
};

constexpr EnumName kWindings[] = {
    {"ccw", GL_CCW},
    {"cw", GL_CW},
};

constexpr EnumName kCompareFunctions[] = {
    {"never", GL_NEVER},     {"less", GL_LESS},         {"equal", GL_EQUAL},
    {"lequal", GL_LEQUAL},   {"greater", GL_GREATER},   {"notequal", GL_NOTEQUAL},
    {"gequal", GL_GEQUAL},   {"always", GL_ALWAYS},
};

// OpenGL 1.1 blend factors (table 4.1 of the 1.1 specification); SRC_ALPHA_SATURATE is a source
// factor only, SRC_COLOR and ONE_MINUS_SRC_COLOR destination factors only.
constexpr EnumName kBlendSourceFactors[] = {
    {"zero", GL_ZERO},
    {"one", GL_ONE},
    {"dst_color", GL_DST_COLOR},
    {"one_minus_dst_color", GL_ONE_MINUS_DST_COLOR},
    {"src_alpha", GL_SRC_ALPHA},
    {"one_minus_src_alpha", GL_ONE_MINUS_SRC_ALPHA},
    {"dst_alpha", GL_DST_ALPHA},
    {"one_minus_dst_alpha", GL_ONE_MINUS_DST_ALPHA},
    {"src_alpha_saturate", GL_SRC_ALPHA_SATURATE},
};
constexpr EnumName kBlendDestinationFactors[] = {
    {"zero", GL_ZERO},
    {"one", GL_ONE},
    {"src_color", GL_SRC_COLOR},
    {"one_minus_src_color", GL_ONE_MINUS_SRC_COLOR},
    {"src_alpha", GL_SRC_ALPHA},
    {"one_minus_src_alpha", GL_ONE_MINUS_SRC_ALPHA},
    {"dst_alpha", GL_DST_ALPHA},
    {"one_minus_dst_alpha", GL_ONE_MINUS_DST_ALPHA},
};

constexpr EnumName kStencilOps[] = {
    {"keep", GL_KEEP}, {"zero", GL_ZERO}, {"replace", GL_REPLACE},
    {"incr", GL_INCR}, {"decr", GL_DECR}, {"invert", GL_INVERT},
};

constexpr EnumName kPolygonModes[] = {
    {"point", GL_POINT},
    {"line", GL_LINE},
    {"fill", GL_FILL},
};

constexpr EnumName kFogModes[] = {
    {"linear", GL_LINEAR},
    {"exp", GL_EXP},
    {"exp2", GL_EXP2},
};

constexpr EnumName kColorMaterialModes[] = {
    {"ambient", GL_AMBIENT},
    {"diffuse", GL_DIFFUSE},
    {"specular", GL_SPECULAR},
    {"emission", GL_EMISSION},
    {"ambient_and_diffuse", GL_AMBIENT_AND_DIFFUSE},
};

constexpr EnumName kColorControls[] = {
    {"single_color", GL_SINGLE_COLOR},
    {"separate_specular_color", GL_SEPARATE_SPECULAR_COLOR},
};

constexpr EnumName kLogicOps[] = {
    {"clear", GL_CLEAR},       {"and", GL_AND},
    {"and_reverse", GL_AND_REVERSE}, {"copy", GL_COPY},
    {"and_inverted", GL_AND_INVERTED}, {"noop", GL_NOOP},
    {"xor", GL_XOR},           {"or", GL_OR},
    {"nor", GL_NOR},           {"equiv", GL_EQUIV},
    {"invert", GL_INVERT},     {"or_reverse", GL_OR_REVERSE},
    {"copy_inverted", GL_COPY_INVERTED}, {"or_inverted", GL_OR_INVERTED},
    {"nand", GL_NAND},         {"set", GL_SET},
};

constexpr EnumName kMinFilters[] = {
    {"nearest", GL_NEAREST},
    {"linear", GL_LINEAR},
    {"nearest_mipmap_nearest", GL_NEAREST_MIPMAP_NEAREST},
    {"linear_mipmap_nearest", GL_LINEAR_MIPMAP_NEAREST},
    {"nearest_mipmap_linear", GL_NEAREST_MIPMAP_LINEAR},
    {"linear_mipmap_linear", GL_LINEAR_MIPMAP_LINEAR},
};
constexpr EnumName kMagFilters[] = {
    {"nearest", GL_NEAREST},
    {"linear", GL_LINEAR},
};

constexpr EnumName kDepthTextureModes[] = {
    {"luminance", GL_LUMINANCE},
    {"intensity", GL_INTENSITY},
    {"alpha", GL_ALPHA},
};

constexpr EnumName kWrapModes[] = {
    {"repeat", GL_REPEAT},
    {"clamp", GL_CLAMP},
    {"clamp_to_edge", GL_CLAMP_TO_EDGE},
    {"clamp_to_border", GL_CLAMP_TO_BORDER},
    {"mirrored_repeat", GL_MIRRORED_REPEAT},
};

constexpr EnumName kTexEnvModes[] = {
    {"modulate", GL_MODULATE}, {"decal", GL_DECAL}, {"replace", GL_REPLACE},
    {"blend", GL_BLEND},       {"add", GL_ADD},
};

constexpr EnumName kTexGenCoords[] = {
    {"s", GL_S}, {"t", GL_T}, {"r", GL_R}, {"q", GL_Q},
};

constexpr EnumName kTexGenModes[] = {
    {"object_linear", GL_OBJECT_LINEAR},
    {"eye_linear", GL_EYE_LINEAR},
    {"sphere_map", GL_SPHERE_MAP},
};

constexpr EnumName kQuadricDrawStyles[] = {
    {"fill", GLU_FILL},
    {"line", GLU_LINE},
    {"silhouette", GLU_SILHOUETTE},
    {"point", GLU_POINT},
};
constexpr EnumName kQuadricNormals[] = {
    {"none", GLU_NONE},
    {"flat", GLU_FLAT},
    {"smooth", GLU_SMOOTH},
};
constexpr EnumName kQuadricOrientations[] = {
    {"outside", GLU_OUTSIDE},
    {"inside", GLU_INSIDE},
};

constexpr EnumName kCurveModes[] = {
    {"line", GL_LINE},
    {"point", GL_POINT},
};

constexpr EnumName kClearBuffers[] = {
    {"color", GL_COLOR_BUFFER_BIT},
    {"depth", GL_DEPTH_BUFFER_BIT},
    {"stencil", GL_STENCIL_BUFFER_BIT},
};

} // namespace

namespace names {
const EnumTable capabilities{kCapabilities};
const EnumTable primitiveModes{kPrimitiveModes};
const EnumTable shadeModels{kShadeModels};
const EnumTable faces{kFaces};
const EnumTable cullFaces{kFaces};
const EnumTable windings{kWindings};
const EnumTable compareFunctions{kCompareFunctions};
const EnumTable blendSourceFactors{kBlendSourceFactors};
const EnumTable blendDestinationFactors{kBlendDestinationFactors};
const EnumTable stencilOps{kStencilOps};
const EnumTable polygonModes{kPolygonModes};
const EnumTable fogModes{kFogModes};
const EnumTable colorMaterialModes{kColorMaterialModes};
const EnumTable colorControls{kColorControls};
const EnumTable logicOps{kLogicOps};
const EnumTable minFilters{kMinFilters};
const EnumTable magFilters{kMagFilters};
const EnumTable depthTextureModes{kDepthTextureModes};
const EnumTable wrapModes{kWrapModes};
const EnumTable texEnvModes{kTexEnvModes};
const EnumTable texGenCoords{kTexGenCoords};
const EnumTable texGenModes{kTexGenModes};
const EnumTable quadricDrawStyles{kQuadricDrawStyles};
const EnumTable quadricNormals{kQuadricNormals};
const EnumTable quadricOrientations{kQuadricOrientations};
const EnumTable curveModes{kCurveModes};
const EnumTable clearBuffers{kClearBuffers};
} // namespace names

bool lookupEnum(EnumTable table, std::string_view name, GLenumValue &value) {
  for (const EnumName &entry : table) {
    if (entry.name == name) {
      value = entry.value;
      return true;
    }
  }
  return false;
}

std::string enumName(EnumTable table, GLenumValue value) {
  for (const EnumName &entry : table) {
    if (entry.value == value) return std::string(entry.name);
  }
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04X", value);
  return buffer;
}

std::string listNames(EnumTable table) {
  std::string out;
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (i > 0) out += (i + 1 == table.size()) ? " or " : ", ";
    out += table[i].name;
  }
  return out;
}

} // namespace glass::scene
