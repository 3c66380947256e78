// The .ifs3 file format: the .ifs format of the plane (ifs_format.h) extended to space, read by
// `glass ifs3d` and by the scene language's `ifs3d` statement, and written by `glass ifs3d fit`.
//
//   # a comment runs to the end of the line
//   name "Sierpinski tetrahedron"      optional
//   base cube                          optional step-0 polyhedron of the rebuild:
//                                        cube (default, [0,1]^3) | tetrahedron | hull |
//                                        "model.obj" (an OBJ file, relative to the .ifs3 file,
//                                        loaded by glass/scene/ifs3_base_model.h)
//   map scale 0.5                      one map per line, any number of lines
//   map translate 0.5 0 0 scale 0.5 color 0.2 0.7 0.3 probability 0.25
//   map matrix 0.5 0 0 0.25  0 0.5 0 0  0 0 0.5 0.5
//                                      the rows a11 a12 a13 t1 a21 a22 a23 t2 a31 a32 a33 t3
//
// A map is a product of operations read left to right, as the GL calls glTranslate, glRotate,
// glScale are issued: `translate 0.5 0 0 scale 0.5` scales first. Operations:
//   translate x y z | rotate DEGREES ax ay az (glRotate: counter-clockwise about the axis) |
//   rotate quaternion w x y z (the rotation of that quaternion, normalised) |
//   scale s | scale sx sy sz | matrix (12 numbers, as above).
// After the operations, optionally: color r g b and probability p (all maps or none), as in 2D.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "glass/geometry/ifs3d.h"
#include "glass/geometry/ifs_format.h"

namespace glass::geometry {

struct Ifs3ParseResult {
  IteratedFunctionSystem3 ifs;
  std::vector<IfsParseError> errors;  // empty on success; format with formatIfsErrors
  bool ok() const { return errors.empty(); }
};

Ifs3ParseResult parseIfs3(std::string_view text);

// Reads and parses a file; a file that cannot be read gives one error at line 0.
Ifs3ParseResult loadIfs3File(const std::string& path);

// The system as .ifs3 text, every map as `matrix` with 17 significant digits (so that reading it
// back gives the same doubles), colours and probabilities kept.
std::string formatIfs3(const IteratedFunctionSystem3& ifs);

}  // namespace glass::geometry
