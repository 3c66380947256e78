// Cube map face selection (OpenGL 1.3 specification, section 3.8.6, table 3.19): the texture
// coordinates (s, t, r) are a direction (rx, ry, rz); the coordinate of largest magnitude, the
// major axis ma, picks the face, and the face is addressed at
//   s' = (sc / |ma| + 1) / 2,   t' = (tc / |ma| + 1) / 2
// with
//   major axis   face                         sc    tc    ma
//   +rx          TEXTURE_CUBE_MAP_POSITIVE_X  -rz   -ry   rx
//   -rx          TEXTURE_CUBE_MAP_NEGATIVE_X  +rz   -ry   rx
//   +ry          TEXTURE_CUBE_MAP_POSITIVE_Y  +rx   +rz   ry
//   -ry          TEXTURE_CUBE_MAP_NEGATIVE_Y  +rx   -rz   ry
//   +rz          TEXTURE_CUBE_MAP_POSITIVE_Z  +rx   -ry   rz
//   -rz          TEXTURE_CUBE_MAP_NEGATIVE_Z  -rx   -ry   rz
// Ties between magnitudes go to x over y over z, as in Mesa.
#pragma once

namespace glass::gl {

struct CubeFaceCoordinates {
  int face = 0;  // 0..5 in the order of the table
  float s = 0.5f, t = 0.5f;
};

// The face the direction points at, and (s', t') on it. The zero vector gives face 0's centre.
CubeFaceCoordinates cubeFaceCoordinates(float rx, float ry, float rz);

// (s', t') of the direction on a given face (the projection of the table for that face, also
// for directions whose major axis is another): used for the differences of a pixel quad.
void cubeFaceProjection(int face, float rx, float ry, float rz, float* s, float* t);

}  // namespace glass::gl
