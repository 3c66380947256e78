#include "glass/geometry/ifs_format.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace glass::geometry {

namespace {

struct Token {
  std::string text;
  int column = 0;     // 1-based
  bool quoted = false;
};

class LineParser {
 public:
  LineParser(std::vector<Token> tokens, int line, std::vector<IfsParseError>& errors, int endColumn)
      : tokens_(std::move(tokens)), line_(line), errors_(errors), endColumn_(endColumn) {}

  bool atEnd() const { return next_ >= tokens_.size(); }
  const Token* peek() const { return atEnd() ? nullptr : &tokens_[next_]; }
  Token take() { return tokens_[next_++]; }
  int column() const { return atEnd() ? endColumn_ : tokens_[next_].column; }

  void error(int column, std::string message) {
    errors_.push_back({line_, column, std::move(message)});
    failed_ = true;
  }
  bool failed() const { return failed_; }

  bool peekIsNumber() const {
    const Token* t = peek();
    return t != nullptr && !t->quoted && parseNumber(t->text).has_value();
  }

  // A number for `what`; reports and returns nothing when missing or malformed.
  std::optional<double> number(std::string_view what) {
    if (atEnd()) {
      error(endColumn_, "expected " + std::string(what) + ", found the end of the line");
      return std::nullopt;
    }
    const Token token = take();
    auto value = token.quoted ? std::nullopt : parseNumber(token.text);
    if (!value) {
      error(token.column, "expected " + std::string(what) + ", found '" + token.text + "'");
    }
    return value;
  }

  // All remaining tokens must have been used.
  void expectEnd() {
    if (!atEnd() && !failed_) error(column(), "unexpected '" + peek()->text + "' at the end of the line");
  }

  static std::optional<double> parseNumber(std::string_view text) {
    double value = 0.0;
    const char* begin = text.data();
    const char* end = text.data() + text.size();
    if (begin != end && *begin == '+') ++begin;  // from_chars does not take a leading '+'
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
    return value;
  }

 private:
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  int line_;
  std::vector<IfsParseError>& errors_;
  int endColumn_;
  bool failed_ = false;
};

std::vector<Token> tokenize(std::string_view line, int lineNumber, std::vector<IfsParseError>& errors) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (c == '#') {
      break;
    } else if (c == '"') {
      const std::size_t close = line.find('"', i + 1);
      if (close == std::string_view::npos) {
        errors.push_back({lineNumber, static_cast<int>(i) + 1, "unterminated string"});
        return {};
      }
      tokens.push_back({std::string(line.substr(i + 1, close - i - 1)), static_cast<int>(i) + 1, true});
      i = close + 1;
    } else {
      std::size_t end = i;
      while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r' &&
             line[end] != '#' && line[end] != '"') {
        ++end;
      }
      tokens.push_back({std::string(line.substr(i, end - i)), static_cast<int>(i) + 1, false});
      i = end;
    }
  }
  return tokens;
}

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
  int operations = 0;
  bool sawAttribute = false;
  while (!p.atEnd() && !p.failed()) {
    const Token word = p.take();
    if (word.text == "translate") {
      auto tx = p.number("translate x"), ty = p.number("translate y");
      if (p.failed()) return;
      map.transform = map.transform * Affine2::translation(*tx, *ty);
    } else if (word.text == "rotate") {
      auto degrees = p.number("an angle in degrees");
      if (p.failed()) return;
      map.transform = map.transform * Affine2::rotationDegrees(*degrees);
    } else if (word.text == "scale") {
      auto sx = p.number("a scale factor");
      if (p.failed()) return;
      const double sy = p.peekIsNumber() ? *p.number("scale y") : *sx;
      map.transform = map.transform * Affine2::scaling(*sx, sy);
    } else if (word.text == "shear") {
      auto h = p.number("a shear factor");
      if (p.failed()) return;
      map.transform = map.transform * Affine2::shear(*h);
    } else if (word.text == "matrix") {
      double v[6];
      for (int i = 0; i < 6; ++i) {
        auto value = p.number("six matrix entries a11 a12 a13 a21 a22 a23");
        if (p.failed()) return;
        v[i] = *value;
      }
      map.transform = map.transform * Affine2::fromRows(v[0], v[1], v[2], v[3], v[4], v[5]);
    } else if (word.text == "color") {
      const int column = p.column();
      auto r = p.number("red"), g = p.number("green"), b = p.number("blue");
      if (p.failed()) return;
      if (*r < 0 || *r > 1 || *g < 0 || *g > 1 || *b < 0 || *b > 1) {
        p.error(column, "colour components must lie in [0, 1]");
        return;
      }
      map.color = IfsColor{static_cast<float>(*r), static_cast<float>(*g), static_cast<float>(*b)};
      sawAttribute = true;
      continue;
    } else if (word.text == "probability") {
      const int column = p.column();
      auto value = p.number("a probability");
      if (p.failed()) return;
      if (*value < 0.0) {
        p.error(column, "a probability cannot be negative");
        return;
      }
      map.probability = *value;
      sawAttribute = true;
      continue;
    } else if (!word.quoted && LineParser::parseNumber(word.text)) {
      p.error(word.column, "unexpected '" + word.text + "': too many numbers for the operation before it");
      return;
    } else {
      p.error(word.column, "unknown map operation '" + word.text +
                               "' (translate, rotate, scale, shear, matrix, color, probability)");
      return;
    }
    if (sawAttribute) {
      p.error(word.column, "put '" + word.text + "' before color and probability");
      return;
    }
    ++operations;
  }
  if (p.failed()) return;
  if (operations == 0) {
    p.error(mapColumn, "a map needs at least one operation (translate, rotate, scale, shear, matrix)");
    return;
  }
  ifs.maps.push_back(map);
}

}  // namespace

IfsParseResult parseIfs(std::string_view text) {
  IfsParseResult result;
  IteratedFunctionSystem& ifs = result.ifs;
  bool sawName = false, sawBase = false;
  std::vector<int> mapLines;  // for the all-or-none probability check
  int lineNumber = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    ++lineNumber;
    std::vector<Token> tokens = tokenize(line, lineNumber, result.errors);
    if (!tokens.empty()) {
      const Token keyword = tokens.front();
      tokens.erase(tokens.begin());
      LineParser p(std::move(tokens), lineNumber, result.errors, static_cast<int>(line.size()) + 1);
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
        if (!p.failed()) mapLines.push_back(lineNumber);
      } else {
        p.error(keyword.column, "unknown statement '" + keyword.text + "' (name, window, base, map)");
      }
      p.expectEnd();
    }
    if (end == text.size()) break;
    start = end + 1;
  }

  if (ifs.maps.empty() && result.errors.empty()) {
    result.errors.push_back({1, 1, "no maps: an IFS needs at least one 'map' line"});
  }
  std::size_t withProbability = 0;
  for (const IfsMap& map : ifs.maps) withProbability += map.probability ? 1 : 0;
  if (withProbability != 0 && withProbability != ifs.maps.size()) {
    for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
      if (!ifs.maps[i].probability) {
        result.errors.push_back({mapLines[i], 1, "this map has no probability, others have: give all or none"});
        break;
      }
    }
  } else if (withProbability != 0) {
    double total = 0.0;
    for (const IfsMap& map : ifs.maps) total += *map.probability;
    if (total <= 0.0) result.errors.push_back({mapLines.back(), 1, "the probabilities add up to 0"});
  }
  return result;
}

IfsParseResult loadIfsFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    IfsParseResult result;
    result.errors.push_back({0, 0, "cannot read the file"});
    return result;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseIfs(text.str());
}

std::string formatIfsErrors(const IfsParseResult& result, std::string_view fileName,
                            std::string_view text) {
  std::string out;
  for (const IfsParseError& error : result.errors) {
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
