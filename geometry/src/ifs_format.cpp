#include "glass/geometry/ifs_format.h"

#include <fstream>
#include <optional>
#include <sstream>

#include "ifs_line_parser.h"

namespace glass::geometry {

namespace {

using ifs_text::LineParser;
using ifs_text::Token;

void parseWindow(LineParser& p, IteratedFunctionSystem& ifs) {
  const int column = p.column();
  auto xMin = p.number("xmin"), xMax = p.number("xmax"), yMin = p.number("ymin"), yMax = p.number("ymax");
  if (p.failed()) return;
  if (!(*xMin < *xMax) || !(*yMin < *yMax)) {
    p.error(column, "window needs xmin < xmax and ymin < ymax");
    return;
  }
  ifs.window = IfsWindow{*xMin, *xMax, *yMin, *yMax};
}

void parseBase(LineParser& p, IteratedFunctionSystem& ifs) {
  if (p.atEnd()) {
    p.error(p.column(), "expected square, triangle or polygon after 'base'");
    return;
  }
  const Token kind = p.take();
  std::vector<glm::dvec2> polygon;
  if (kind.text == "square") {
    polygon = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  } else if (kind.text == "triangle" || kind.text == "polygon") {
    const std::size_t wanted = kind.text == "triangle" ? 3 : 0;  // 0: any number >= 3
    while (!p.atEnd() && (wanted == 0 || polygon.size() < wanted)) {
      auto x = p.number("a vertex x"), y = p.number("a vertex y");
      if (p.failed()) return;
      polygon.push_back({*x, *y});
    }
    if (polygon.size() < 3 || (wanted != 0 && polygon.size() != wanted)) {
      p.error(p.column(), kind.text == "triangle" ? "a triangle needs 3 vertices (6 numbers)"
                                                  : "a polygon needs at least 3 vertices");
      return;
    }
  } else {
    p.error(kind.column, "unknown base '" + kind.text + "' (square, triangle or polygon)");
    return;
  }
  ifs.base = std::move(polygon);
}

void parseMap(LineParser& p, IteratedFunctionSystem& ifs, int mapColumn) {
  IfsMap map;
  ifs_text::MapEnding ending;
  const auto operation = [&](const Token& word) {
    using ifs_text::OperationRead;
    if (word.text == "translate") {
      auto tx = p.number("translate x"), ty = p.number("translate y");
      if (p.failed()) return OperationRead::Failed;
      map.transform = map.transform * Affine2::translation(*tx, *ty);
    } else if (word.text == "rotate") {
      auto degrees = p.number("an angle in degrees");
      if (p.failed()) return OperationRead::Failed;
      map.transform = map.transform * Affine2::rotationDegrees(*degrees);
    } else if (word.text == "scale") {
      auto sx = p.number("a scale factor");
      if (p.failed()) return OperationRead::Failed;
      const double sy = p.peekIsNumber() ? *p.number("scale y") : *sx;
      map.transform = map.transform * Affine2::scaling(*sx, sy);
    } else if (word.text == "shear") {
      auto h = p.number("a shear factor");
      if (p.failed()) return OperationRead::Failed;
      map.transform = map.transform * Affine2::shear(*h);
    } else if (word.text == "matrix") {
      double v[6];
      for (int i = 0; i < 6; ++i) {
        auto value = p.number("six matrix entries a11 a12 a13 a21 a22 a23");
        if (p.failed()) return OperationRead::Failed;
        v[i] = *value;
      }
      map.transform = map.transform * Affine2::fromRows(v[0], v[1], v[2], v[3], v[4], v[5]);
    } else {
      return OperationRead::Unknown;
    }
    return OperationRead::Done;
  };
  if (!ifs_text::readMapLine(p, mapColumn, "translate, rotate, scale, shear, matrix", operation, ending)) return;
  map.color = ending.color;
  map.probability = ending.probability;
  ifs.maps.push_back(map);
}

}  // namespace

IfsParseResult parseIfs(std::string_view text) {
  IfsParseResult result;
  IteratedFunctionSystem& ifs = result.ifs;
  bool sawName = false, sawBase = false;
  std::vector<int> mapLines;  // for the all-or-none probability check
  ifs_text::forEachStatement(text, result.errors, [&](const Token& keyword, LineParser& p) {
    if (keyword.text == "name" && !keyword.quoted) {
      if (sawName) p.error(keyword.column, "the name is given twice");
      if (p.atEnd() || !p.peek()->quoted) {
        p.error(p.column(), "expected a quoted name, like name \"Sierpinski triangle\"");
      } else {
        ifs.name = p.take().text;
      }
      sawName = true;
    } else if (keyword.text == "window" && !keyword.quoted) {
      if (ifs.window) p.error(keyword.column, "the window is given twice");
      parseWindow(p, ifs);
    } else if (keyword.text == "base" && !keyword.quoted) {
      if (sawBase) p.error(keyword.column, "the base figure is given twice");
      sawBase = true;
      parseBase(p, ifs);
    } else if (keyword.text == "map" && !keyword.quoted) {
      parseMap(p, ifs, keyword.column);
      if (!p.failed()) mapLines.push_back(p.line());
    } else {
      p.error(keyword.column, "unknown statement '" + keyword.text + "' (name, window, base, map)");
    }
  });

  if (ifs.maps.empty() && result.errors.empty()) {
    result.errors.push_back({1, 1, "no maps: an IFS needs at least one 'map' line"});
  }
  std::vector<std::optional<double>> probabilities;
  for (const IfsMap& map : ifs.maps) probabilities.push_back(map.probability);
  ifs_text::checkProbabilities(probabilities, mapLines, result.errors);
  return result;
}

std::optional<std::string> readIfsText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return text.str();
}

IfsParseResult loadIfsFile(const std::string& path) {
  const std::optional<std::string> text = readIfsText(path);
  if (!text) {
    IfsParseResult result;
    result.errors.push_back({0, 0, "cannot read the file"});
    return result;
  }
  return parseIfs(*text);
}

std::string formatIfsErrors(const IfsParseResult& result, std::string_view fileName,
                            std::string_view text) {
  return formatIfsErrors(std::span<const IfsParseError>(result.errors), fileName, text);
}

std::string formatIfsErrors(std::span<const IfsParseError> errors, std::string_view fileName,
                            std::string_view text) {
  std::string out;
  for (const IfsParseError& error : errors) {
    // Appended piece by piece: GCC 12 misreports operator+ chains on strings (-Wrestrict).
    out += fileName;
    if (error.line > 0) {
      out += ':';
      out += std::to_string(error.line);
      out += ':';
      out += std::to_string(error.column);
    }
    out += ": error: ";
    out += error.message;
    out += '\n';
    if (error.line <= 0) continue;
    // The offending line and a caret under the column.
    std::size_t start = 0;
    for (int line = 1; line < error.line && start != std::string_view::npos; ++line) {
      start = text.find('\n', start);
      if (start != std::string_view::npos) ++start;
    }
    if (start == std::string_view::npos || start > text.size()) continue;
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string source(text.substr(start, end - start));
    if (!source.empty() && source.back() == '\r') source.pop_back();
    out += "  ";
    out += source;
    out += "\n  ";
    for (int c = 1; c < error.column; ++c) out += (c - 1 < static_cast<int>(source.size()) && source[c - 1] == '\t') ? '\t' : ' ';
    out += "^\n";
  }
  return out;
}

}  // namespace glass::geometry
