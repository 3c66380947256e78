// The IFS file format, read by `glass ifs` and by the scene language's `ifs` statement.
//
//   # a comment runs to the end of the line
//   name "Sierpinski triangle"          optional
//   window -0.1 1.1 -0.1 1.1            optional: xmin xmax ymin ymax (Listing 5's constants);
//                                       without it the window is fitted to the attractor
//   base triangle 1 0  0 1  0 0         optional step-0 figure (default: the unit square):
//                                         base square | base triangle x y x y x y |
//                                         base polygon x y x y x y ... (convex, counter-clockwise)
//   map scale 0.5                       one map per line, any number of lines
//   map translate 0.5 0 scale 0.5 color 0.2 0.7 0.3 probability 0.25
//   map matrix 0 -0.5 0.5  0.5 0 0      the rows a11 a12 a13 a21 a22 a23 of [A; 0 0 1]
//
// A map is a product of operations read left to right, as the GL calls glTranslate, glRotate,
// glScale are issued: `translate 0.5 0 scale 0.5` is T(0.5, 0) S(0.5), which scales first.
// Operations: translate tx ty | rotate degrees (counter-clockwise) | scale s | scale sx sy |
// shear h (x += h y) | matrix a11 a12 a13 a21 a22 a23. After the operations, optionally:
// color r g b (each in [0, 1]) and probability p (p >= 0; all maps or none).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glass/geometry/ifs.h"

namespace glass::geometry {

struct IfsParseError {
  int line = 0;    // 1-based
  int column = 0;  // 1-based, of the offending token
  std::string message;
};

struct IfsParseResult {
  IteratedFunctionSystem ifs;
  std::vector<IfsParseError> errors;  // empty on success
  bool ok() const { return errors.empty(); }
};

IfsParseResult parseIfs(std::string_view text);

// Reads and parses a file; a file that cannot be read gives one error at line 0.
IfsParseResult loadIfsFile(const std::string& path);

// The whole file as text, or nothing when it cannot be read.
std::optional<std::string> readIfsText(const std::string& path);

// "file:line:col: message" lines, with the offending source line and a caret under the column.
std::string formatIfsErrors(const IfsParseResult& result, std::string_view fileName,
                            std::string_view text);
// The same for any list of errors (the .ifs3 format's too, ifs3d_format.h).
std::string formatIfsErrors(std::span<const IfsParseError> errors, std::string_view fileName,
                            std::string_view text);

}  // namespace glass::geometry
