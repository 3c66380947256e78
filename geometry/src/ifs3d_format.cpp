#include "glass/geometry/ifs3d_format.h"

#include <cstdio>

#include "glass/geometry/quaternion.h"
#include "ifs_line_parser.h"

namespace glass::geometry {

namespace {

using ifs_text::LineParser;
using ifs_text::Token;

void parseBase(LineParser& p, IteratedFunctionSystem3& ifs) {
  if (p.atEnd()) {
    p.error(p.column(), "expected cube, tetrahedron, hull or a quoted OBJ file name after 'base'");
    return;
  }
  const Token kind = p.take();
  if (kind.text == "cube" && !kind.quoted) {
    ifs.base = IfsBase3::Cube;
  } else if (kind.text == "tetrahedron" && !kind.quoted) {
    ifs.base = IfsBase3::Tetrahedron;
  } else if (kind.text == "hull" && !kind.quoted) {
    ifs.base = IfsBase3::Hull;
  } else if (kind.quoted) {
    if (kind.text.empty()) {
      p.error(kind.column, "the base model's file name is empty");
      return;
    }
    ifs.base = IfsBase3::Model;
    ifs.baseModelPath = kind.text;
    ifs.baseModelLine = p.line();
    ifs.baseModelColumn = kind.column;
  } else {
    p.error(kind.column, "unknown base '" + kind.text + "' (cube, tetrahedron, hull or \"model.obj\")");
  }
}

// n numbers for `what`, or nothing after reporting.
template <std::size_t N>
std::optional<std::array<double, N>> numbers(LineParser& p, std::string_view what) {
  std::array<double, N> values{};
  for (std::size_t i = 0; i < N; ++i) {
    auto v = p.number(what);
    if (!v) return std::nullopt;
    values[i] = *v;
  }
  return values;
}

void parseMap(LineParser& p, IteratedFunctionSystem3& ifs, int mapColumn) {
  IfsMap3 map;
  ifs_text::MapEnding ending;
  const auto operation = [&](const Token& word) {
    using ifs_text::OperationRead;
    if (word.text == "translate") {
      auto t = numbers<3>(p, "translate x y z");
      if (!t) return OperationRead::Failed;
      map.transform = map.transform * Affine3::translation({(*t)[0], (*t)[1], (*t)[2]});
    } else if (word.text == "rotate") {
      if (!p.atEnd() && p.peek()->text == "quaternion") {
        p.take();
        const int column = p.column();
        auto q = numbers<4>(p, "a quaternion w x y z");
        if (!q) return OperationRead::Failed;
        const Quaternion quaternion{(*q)[0], (*q)[1], (*q)[2], (*q)[3]};
        if (!(normSquared(quaternion) > 0.0)) {
          p.error(column, "the zero quaternion is no rotation");
          return OperationRead::Failed;
        }
        map.transform = map.transform * Affine3::fromParts(rotationMatrix(quaternion), glm::dvec3(0.0));
      } else {
        auto degrees = p.number("an angle in degrees");
        if (!degrees) return OperationRead::Failed;
        const int column = p.column();
        auto axis = numbers<3>(p, "a rotation axis x y z");
        if (!axis) return OperationRead::Failed;
        const glm::dvec3 a{(*axis)[0], (*axis)[1], (*axis)[2]};
        if (a == glm::dvec3(0.0)) {
          p.error(column, "the rotation axis cannot be 0 0 0");
          return OperationRead::Failed;
        }
        map.transform = map.transform * Affine3::rotationDegrees(*degrees, a);
      }
    } else if (word.text == "scale") {
      auto sx = p.number("a scale factor");
      if (!sx) return OperationRead::Failed;
      glm::dvec3 s(*sx);
      if (p.peekIsNumber()) {
        auto rest = numbers<2>(p, "scale y z (one factor, or three)");
        if (!rest) return OperationRead::Failed;
        s.y = (*rest)[0];
        s.z = (*rest)[1];
      }
      map.transform = map.transform * Affine3::scaling(s);
    } else if (word.text == "matrix") {
      auto v = numbers<12>(p, "twelve matrix entries a11 a12 a13 t1 a21 a22 a23 t2 a31 a32 a33 t3");
      if (!v) return OperationRead::Failed;
      map.transform = map.transform * Affine3::fromRows(*v);
    } else {
      return OperationRead::Unknown;
    }
    return OperationRead::Done;
  };
  if (!ifs_text::readMapLine(p, mapColumn, "translate, rotate, scale, matrix", operation, ending)) return;
  map.color = ending.color;
  map.probability = ending.probability;
  ifs.maps.push_back(map);
}

}  // namespace

Ifs3ParseResult parseIfs3(std::string_view text) {
  Ifs3ParseResult result;
  IteratedFunctionSystem3& ifs = result.ifs;
  bool sawName = false, sawBase = false;
  std::vector<int> mapLines;
  ifs_text::forEachStatement(text, result.errors, [&](const Token& keyword, LineParser& p) {
    if (keyword.text == "name" && !keyword.quoted) {
      if (sawName) p.error(keyword.column, "the name is given twice");
      if (p.atEnd() || !p.peek()->quoted) {
        p.error(p.column(), "expected a quoted name, like name \"Sierpinski tetrahedron\"");
      } else {
        ifs.name = p.take().text;
      }
      sawName = true;
    } else if (keyword.text == "base" && !keyword.quoted) {
      if (sawBase) p.error(keyword.column, "the base polyhedron is given twice");
      sawBase = true;
      parseBase(p, ifs);
    } else if (keyword.text == "map" && !keyword.quoted) {
      parseMap(p, ifs, keyword.column);
      if (!p.failed()) mapLines.push_back(p.line());
    } else if (keyword.text == "window" && !keyword.quoted) {
      p.error(keyword.column, "'window' belongs to the 2D .ifs format; a .ifs3 view is chosen when rendering");
    } else {
      p.error(keyword.column, "unknown statement '" + keyword.text + "' (name, base, map)");
    }
  });
  if (ifs.maps.empty() && result.errors.empty()) {
    result.errors.push_back({1, 1, "no maps: an IFS needs at least one 'map' line"});
  }
  std::vector<std::optional<double>> probabilities;
  for (const IfsMap3& map : ifs.maps) probabilities.push_back(map.probability);
  ifs_text::checkProbabilities(probabilities, mapLines, result.errors);
  return result;
}

Ifs3ParseResult loadIfs3File(const std::string& path) {
  const std::optional<std::string> text = readIfsText(path);
  if (!text) {
    Ifs3ParseResult result;
    result.errors.push_back({0, 0, "cannot read the file"});
    return result;
  }
  return parseIfs3(*text);
}

std::string formatIfs3(const IteratedFunctionSystem3& ifs) {
  std::string out;
  char text[64];
  if (!ifs.name.empty()) out += "name \"" + ifs.name + "\"\n";
  if (ifs.base == IfsBase3::Tetrahedron) out += "base tetrahedron\n";
  if (ifs.base == IfsBase3::Hull) out += "base hull\n";
  if (ifs.base == IfsBase3::Model) out += "base \"" + ifs.baseModelPath + "\"\n";
  for (const IfsMap3& map : ifs.maps) {
    out += "map matrix";
    for (int r = 0; r < 3; ++r) {
      out += r == 0 ? " " : "  ";
      for (int c = 0; c < 4; ++c) {
        // -0 prints as 0: the sign of a zero entry means nothing here.
        std::snprintf(text, sizeof text, "%s%.17g", c ? " " : "", map.transform.m[r][c] + 0.0);
        out += text;
      }
    }
    if (map.color) {
      std::snprintf(text, sizeof text, " color %.6g %.6g %.6g", map.color->r, map.color->g, map.color->b);
      out += text;
    }
    if (map.probability) {
      std::snprintf(text, sizeof text, " probability %.6g", *map.probability);
      out += text;
    }
    out += '\n';
  }
  return out;
}

}  // namespace glass::geometry
