#include "ifs_line_parser.h"

#include <charconv>
#include <cmath>

#include "glass/geometry/byte_order_mark.h"

namespace glass::geometry::ifs_text {

void LineParser::error(int column, std::string message) {
  errors_.push_back({line_, column, std::move(message)});
  failed_ = true;
}

bool LineParser::peekIsNumber() const {
  const Token* t = peek();
  return t != nullptr && !t->quoted && parseNumber(t->text).has_value();
}

std::optional<double> LineParser::number(std::string_view what) {
  if (atEnd()) {
    error(endColumn_, "expected " + std::string(what) + ", found the end of the line");
    return std::nullopt;
  }
  const Token token = take();
  auto value = token.quoted ? std::nullopt : parseNumber(token.text);
  if (!value) error(token.column, "expected " + std::string(what) + ", found '" + token.text + "'");
  return value;
}

void LineParser::expectEnd() {
  if (!atEnd() && !failed_) error(column(), "unexpected '" + peek()->text + "' at the end of the line");
}

std::optional<double> LineParser::parseNumber(std::string_view text) {
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars does not take a leading '+'
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

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

void forEachStatement(std::string_view text, std::vector<IfsParseError>& errors,
                      const std::function<void(const Token& keyword, LineParser& line)>& statement) {
  int lineNumber = 0;
  std::size_t start = byteOrderMarkLength(text);
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    ++lineNumber;
    std::vector<Token> tokens = tokenize(line, lineNumber, errors);
    if (!tokens.empty()) {
      const Token keyword = tokens.front();
      tokens.erase(tokens.begin());
      LineParser p(std::move(tokens), lineNumber, errors, static_cast<int>(line.size()) + 1);
      statement(keyword, p);
      p.expectEnd();
    }
    if (end == text.size()) break;
    start = end + 1;
  }
}

std::optional<IfsColor> readColor(LineParser& p) {
  const int column = p.column();
  auto r = p.number("red"), g = p.number("green"), b = p.number("blue");
  if (p.failed()) return std::nullopt;
  if (*r < 0 || *r > 1 || *g < 0 || *g > 1 || *b < 0 || *b > 1) {
    p.error(column, "colour components must lie in [0, 1]");
    return std::nullopt;
  }
  return IfsColor{static_cast<float>(*r), static_cast<float>(*g), static_cast<float>(*b)};
}

std::optional<double> readProbability(LineParser& p) {
  const int column = p.column();
  auto value = p.number("a probability");
  if (p.failed()) return std::nullopt;
  if (*value < 0.0) {
    p.error(column, "a probability cannot be negative");
    return std::nullopt;
  }
  return value;
}

bool readMapLine(LineParser& p, int mapColumn, std::string_view operationNames,
                 const std::function<OperationRead(const Token& word)>& operation, MapEnding& ending) {
  int operations = 0;
  bool sawEnding = false;
  while (!p.atEnd() && !p.failed()) {
    const Token word = p.take();
    if (word.text == "color") {
      ending.color = readColor(p);
      sawEnding = true;
      continue;
    }
    if (word.text == "probability") {
      ending.probability = readProbability(p);
      sawEnding = true;
      continue;
    }
    const OperationRead read = operation(word);
    if (read == OperationRead::Failed || p.failed()) return false;
    if (read == OperationRead::Unknown) {
      if (!word.quoted && LineParser::parseNumber(word.text)) {
        p.error(word.column, "unexpected '" + word.text + "': too many numbers for the operation before it");
      } else {
        p.error(word.column, "unknown map operation '" + word.text + "' (" + std::string(operationNames) + ", color, probability)");
      }
      return false;
    }
    if (sawEnding) {
      p.error(word.column, "put '" + word.text + "' before color and probability");
      return false;
    }
    ++operations;
  }
  if (p.failed()) return false;
  if (operations == 0) {
    p.error(mapColumn, "a map needs at least one operation (" + std::string(operationNames) + ")");
    return false;
  }
  return true;
}

void checkProbabilities(std::span<const std::optional<double>> probabilities, std::span<const int> mapLines,
                        std::vector<IfsParseError>& errors) {
  std::size_t given = 0;
  for (const auto& p : probabilities) given += p ? 1 : 0;
  if (given != 0 && given != probabilities.size()) {
    for (std::size_t i = 0; i < probabilities.size(); ++i) {
      if (!probabilities[i]) {
        errors.push_back({mapLines[i], 1, "this map has no probability, others have: give all or none"});
        break;
      }
    }
  } else if (given != 0) {
    double total = 0.0;
    for (const auto& p : probabilities) total += *p;
    if (total <= 0.0) errors.push_back({mapLines.back(), 1, "the probabilities add up to 0"});
  }
}

}  // namespace glass::geometry::ifs_text
