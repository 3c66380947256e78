// The colour scales of glass's teaching views, shared by `glass render --view` (scene/) and the
// GLASS_VIEW pictures of any GL program (pipeline/src/teaching/), so that one count or one level
// has one colour wherever a student sees it (docs/teaching.md shows the scales).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>

namespace glass::geometry {

// The heat map of fragment counts: one step per count, dark to bright, so that a pixel's count
// can be read off the picture; 8 or more is white.
inline std::array<std::uint8_t, 3> overdrawScaleColor(int count) {
  static constexpr std::array<std::uint8_t, 3> scale[] = {
      {0, 0, 0},       // 0: nothing drawn
      {30, 40, 140},   // 1
      {0, 120, 210},   // 2
      {0, 180, 120},   // 3
      {120, 210, 0},   // 4
      {240, 220, 0},   // 5
      {250, 140, 0},   // 6
      {230, 40, 30},   // 7
      {255, 255, 255}, // 8 or more
  };
  const int last = static_cast<int>(std::size(scale)) - 1;
  return scale[std::clamp(count, 0, last)];
}

// The number of counts the heat map tells apart (the last stands for that many or more).
inline constexpr int kOverdrawScaleSteps = 9;

// The mipmap view's colours: one per level, in rainbow order from the base image (level 0, red)
// to the smallest, so that a receding floor shows bands; 9 or more is white.
inline constexpr int kMipmapScaleSteps = 10;
inline std::array<std::uint8_t, 3> mipmapScaleColor(int level) {
  static constexpr std::array<std::uint8_t, 3> scale[kMipmapScaleSteps] = {
      {255, 0, 0},     // 0 red
      {255, 128, 0},   // 1 orange
      {255, 255, 0},   // 2 yellow
      {0, 200, 0},     // 3 green
      {0, 220, 220},   // 4 cyan
      {0, 64, 255},    // 5 blue
      {140, 0, 255},   // 6 purple
      {255, 0, 255},   // 7 magenta
      {255, 160, 200}, // 8 pink
      {255, 255, 255}, // 9 or more white
  };
  return scale[std::clamp(level, 0, kMipmapScaleSteps - 1)];
}
inline const char* mipmapScaleName(int level) {
  static constexpr const char* names[kMipmapScaleSteps] = {
      "red", "orange", "yellow", "green", "cyan", "blue", "purple", "magenta", "pink", "white"};
  return names[std::clamp(level, 0, kMipmapScaleSteps - 1)];
}
// Fragments drawn without a texture.
inline constexpr std::array<std::uint8_t, 3> kMipmapUntexturedColor = {96, 96, 96};

}  // namespace glass::geometry
