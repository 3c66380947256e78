// The line-by-line reading shared by the IFS file formats of the plane (.ifs, ifs_format.h) and of
// space (.ifs3, ifs3d_format.h): tokens with their columns, numbers, the colour and probability
// that end a map, and the check that probabilities are given to all maps or to none.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glass/geometry/ifs.h"
#include "glass/geometry/ifs_format.h"

namespace glass::geometry::ifs_text {

struct Token {
  std::string text;
  int column = 0;  // 1-based
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
  int line() const { return line_; }

  void error(int column, std::string message);
  bool failed() const { return failed_; }

  bool peekIsNumber() const;
  // A number for `what`; reports and returns nothing when missing or malformed.
  std::optional<double> number(std::string_view what);
  // All remaining tokens must have been used.
  void expectEnd();

  static std::optional<double> parseNumber(std::string_view text);

 private:
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  int line_;
  std::vector<IfsParseError>& errors_;
  int endColumn_;
  bool failed_ = false;
};

// The tokens of one line: words, numbers and "quoted strings"; `#` starts a comment.
std::vector<Token> tokenize(std::string_view line, int lineNumber, std::vector<IfsParseError>& errors);

// Calls `statement` for each line that has tokens, with the first token (the keyword) taken off;
// then checks that the line's tokens were all used.
void forEachStatement(std::string_view text, std::vector<IfsParseError>& errors,
                      const std::function<void(const Token& keyword, LineParser& line)>& statement);

// `color r g b` after the keyword: each component in [0, 1].
std::optional<IfsColor> readColor(LineParser& p);
// `probability p` after the keyword: p >= 0.
std::optional<double> readProbability(LineParser& p);

// A `map` line: operations, then optionally `color` and `probability`, which end the map.
// operation(word) reads the numbers of one operation and says how it went.
enum class OperationRead { Done, Failed, Unknown };
struct MapEnding {
  std::optional<IfsColor> color;
  std::optional<double> probability;
};
// False when the line has an error (reported). `operationNames` lists the operations for
// messages: "translate, rotate, scale, matrix".
bool readMapLine(LineParser& p, int mapColumn, std::string_view operationNames,
                 const std::function<OperationRead(const Token& word)>& operation, MapEnding& ending);

// Probabilities must be given to every map or to none, and must not all be 0. mapLines[i] is the
// line of map i.
void checkProbabilities(std::span<const std::optional<double>> probabilities, std::span<const int> mapLines,
                        std::vector<IfsParseError>& errors);

}  // namespace glass::geometry::ifs_text
