// The starting orientations of the homework 3 fit's searches (ifs3d_fit.h): the 24 rotations of
// the cube, each also after two fixed turns that fall between them, so no rotation is far from a
// start (about 15 degrees at most); and each of these with a reflection (-Q), since one map of a
// system may reflect. 144 in all, the 48 signed axis permutations among them.
#pragma once

#include <vector>

#include <glm/mat3x3.hpp>

namespace glass::course {

std::vector<glm::dmat3> startingOrientations();

}  // namespace glass::course
