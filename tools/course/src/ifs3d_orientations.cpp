#include "glass/course/ifs3d_orientations.h"

#include <glm/matrix.hpp>

#include "glass/geometry/rotation.h"

namespace glass::course {

namespace g = glass::geometry;

std::vector<glm::dmat3> startingOrientations() {
  std::vector<glm::dmat3> cube;
  const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : permutations) {
    for (int signs = 0; signs < 8; ++signs) {
      glm::dmat3 q(0.0);
      for (int c = 0; c < 3; ++c) q[c][p[c]] = (signs >> c) & 1 ? -1.0 : 1.0;
      if (glm::determinant(q) > 0.0) cube.push_back(q);
    }
  }
  const glm::dmat3 offsets[3] = {glm::dmat3(1.0), g::rotationMatrixDegrees({1.0, 1.0, 1.0}, 40.0),
                                 g::rotationMatrixDegrees({1.0, -2.0, 0.5}, 35.0)};
  std::vector<glm::dmat3> out;
  for (const glm::dmat3& offset : offsets) {
    for (const glm::dmat3& q : cube) {
      out.push_back(q * offset);
      out.push_back(-(q * offset));
    }
  }
  return out;
}

}  // namespace glass::course
