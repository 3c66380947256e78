// Pixel transfer state (OpenGL 1.5 specification, sections 3.6.3 and 3.6.5; tables 6.16 and
// 6.17): glPixelTransfer's scales, biases, index shift and offset and map switches, glPixelMap's
// ten lookup tables, and glPixelZoom's factors.
#pragma once

#include <GL/gl.h>

#include <array>
#include <vector>

namespace glass::gl {

// GL_MAX_PIXEL_MAP_TABLE, as in Mesa.
inline constexpr int kMaxPixelMapTable = 256;
// The maps in the order of their enums, GL_PIXEL_MAP_I_TO_I (0x0C70) .. GL_PIXEL_MAP_A_TO_A (0x0C79).
inline constexpr int kPixelMapCount = 10;

struct PixelTransferState {
  bool mapColor = false;                        // GL_MAP_COLOR
  bool mapStencil = false;                      // GL_MAP_STENCIL
  int indexShift = 0;                           // GL_INDEX_SHIFT
  int indexOffset = 0;                          // GL_INDEX_OFFSET
  float scale[4] = {1.0f, 1.0f, 1.0f, 1.0f};    // GL_RED_SCALE .. GL_ALPHA_SCALE
  float bias[4] = {0.0f, 0.0f, 0.0f, 0.0f};     // GL_RED_BIAS .. GL_ALPHA_BIAS
  float depthScale = 1.0f;                      // GL_DEPTH_SCALE
  float depthBias = 0.0f;                       // GL_DEPTH_BIAS

  // Table 3.3: every map starts with one entry, 0.
  std::array<std::vector<float>, kPixelMapCount> maps{
      {{0.0f}, {0.0f}, {0.0f}, {0.0f}, {0.0f}, {0.0f}, {0.0f}, {0.0f}, {0.0f}, {0.0f}}};

  float zoomX = 1.0f;                           // glPixelZoom
  float zoomY = 1.0f;

  GLenum readBuffer = GL_FRONT;                 // glReadBuffer (fragment/buffer_selection.h)

  const std::vector<float>& map(GLenum name) const { return maps[name - GL_PIXEL_MAP_I_TO_I]; }
};

inline bool isPixelMapName(GLenum name) {
  return name >= GL_PIXEL_MAP_I_TO_I && name < GL_PIXEL_MAP_I_TO_I + kPixelMapCount;
}

// Maps whose input is an index (I_TO_*, S_TO_S): their size must be a power of two (3.6.3).
inline bool isIndexInputMap(GLenum name) {
  return name == GL_PIXEL_MAP_S_TO_S || (name >= GL_PIXEL_MAP_I_TO_I && name <= GL_PIXEL_MAP_I_TO_A);
}

// Maps whose output is an index (I_TO_I, S_TO_S): their values are not clamped.
inline bool isIndexOutputMap(GLenum name) {
  return name == GL_PIXEL_MAP_I_TO_I || name == GL_PIXEL_MAP_S_TO_S;
}

}  // namespace glass::gl
