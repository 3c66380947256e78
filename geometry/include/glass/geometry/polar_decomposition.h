// An affine map of space as translation x rotation x scaling, f = T R S, for the animation of
// homework 3 ("each of 4 transformations as a composition of translation, rotation, and
// scaling"). The linear part L is split by its polar decomposition L = R S (R orthogonal, S
// symmetric), computed from the singular value decomposition L = U diag(s) V^T:
//   R = U V^T, a rotation (det +1);
//   S = V diag(s1, s2, s3) V^T, scaling by s_i along the stretch axes v_i (the columns of V).
// A map that reverses orientation (a reflection, det L < 0) gets a negative scale on its least
// stretched axis, so R stays a rotation; a map that shears is a scaling along axes of its own
// (not x, y, z), which is what a shear is once the rotation is taken out. A similarity has equal
// |s_i| and any axes.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "glass/geometry/affine3d.h"
#include "glass/geometry/quaternion.h"

namespace glass::geometry {

// Eigenvalues (descending) and orthonormal eigenvectors (columns, a rotation: det +1) of a
// symmetric matrix, by cyclic Jacobi rotations to convergence.
struct SymmetricEigen {
  glm::dvec3 values{0.0};
  glm::dmat3 vectors{1.0};
};
SymmetricEigen symmetricEigen(const glm::dmat3& symmetric);

struct TrsDecomposition {
  glm::dvec3 translation{0.0};
  Quaternion rotation;           // R, w >= 0
  glm::dmat3 rotationMatrix{1.0};  // R itself (U V^T), kept for exact recomposition
  glm::dmat3 stretchAxes{1.0};   // V: columns v1, v2, v3, a rotation
  glm::dvec3 scales{1.0};        // s1 >= s2 >= |s3|; s3 < 0 for a reflection
  bool similarity = false;       // |s1| = |s2| = |s3| within 1e-9 relative
  bool reflection = false;       // det L < 0

  glm::dmat3 stretch() const;    // S = V diag(s) V^T
  Affine3 product() const;       // T R S

  // The animation from the identity (t = 0) to the map (t = 1) in three equal phases: the
  // scaling S(u) = V diag(1 + u (s - 1)) V^T, then the rotation slerp(1, q, u) (quaternion
  // spherical interpolation along the shorter arc), then the translation u t.
  Affine3 at(double t) const;
};

TrsDecomposition decomposeTrs(const Affine3& map);

}  // namespace glass::geometry
