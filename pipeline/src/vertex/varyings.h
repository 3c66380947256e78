// What each varying slot of a raster::ClipVertex / WindowVertex / Fragment holds. The vertex
// stage fills them, clipping and the rasterizer interpolate them, the fragment stage reads them.
//
// Only a prefix of the slots is interpolated: the state decides how many are needed
// (varyingCountFor), so a plain coloured triangle interpolates 4 values, not 19.
#pragma once

namespace glass::gl::varying {

inline constexpr int kPrimaryColor = 0;    // r, g, b, a in [0, 1]
inline constexpr int kSecondaryColor = 4;  // r, g, b, a: the separate specular colour (spec 2.13.1)
inline constexpr int kFogCoordinate = 8;   // eye distance |z_e| by default (see fog_hooks.h)
inline constexpr int kTexCoord = 9;        // s, t, r, q of texture unit 0 (after texgen, matrix)
inline constexpr int kEyePosition = 13;    // x_e, y_e, z_e (divided by w_e), for Phong shading
inline constexpr int kEyeNormal = 16;      // the eye-space normal, for Phong shading
inline constexpr int kTexCoordUnit1 = 19;  // s, t, r, q of texture units 1, 2, ..., four slots each

// The first slot of texture unit `unit`'s coordinates.
constexpr int texCoordSlot(int unit) {
  return unit == 0 ? kTexCoord : kTexCoordUnit1 + 4 * (unit - 1);
}

// Prefix lengths: the number of slots to interpolate when a stage needs its slots.
inline constexpr int kCountPrimary = 4;
inline constexpr int kCountSecondary = 8;
inline constexpr int kCountFog = 9;
inline constexpr int kCountTexture = 13;
inline constexpr int kCountPhong = 19;
// The prefix that holds the coordinates of texture units 0 .. units - 1.
constexpr int countForTextureUnits(int units) {
  return units <= 1 ? kCountTexture : texCoordSlot(units - 1) + 4;
}

}  // namespace glass::gl::varying
