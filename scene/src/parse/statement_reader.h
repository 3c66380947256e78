// Reading the arguments of one statement. A statement is a name followed by positional values
// and then named parameters (`sphere radius 2 slices 32`), all on one logical line. Every read
// checks what it reads and throws StatementError with the place and a message that says what was
// expected; the parser reports it and skips to the next statement.
#pragma once

#include "gl_names.h"
#include "glass/scene/lexer.h"
#include "glass/scene/program.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glass::scene {

struct StatementError {
  SourceLocation where;
  int length = 1;
  std::string message;
  std::vector<std::pair<SourceLocation, std::string>> notes;
};

class TokenCursor {
public:
  explicit TokenCursor(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}
  const Token &peek() const { return tokens_[index_]; }
  const Token &next();
  // Moves past the next end of line (or to the end of the file).
  void skipStatement();
  // Where the statement starting at the current token ends (its end-of-line token).
  SourceLocation statementEnd() const;

private:
  std::vector<Token> tokens_;
  std::size_t index_ = 0;
};

// What the reader needs from the parser: the declared parameters, for `$name`.
class ParameterScope {
public:
  virtual ~ParameterScope() = default;
  // The parameter called `name`, marked as used, or null. `index` receives its position.
  virtual Parameter *findParameter(const std::string &name, int &index) = 0;
  // Called when a parameter's value is needed as a constant while parsing (an integer count);
  // from then on the parameter must not be animated.
  virtual void noteConstantUse(int index, SourceLocation at) = 0;
};

// "did you mean 'x'?" for a misspelt name, or an empty string.
std::string suggestName(std::string_view wrong, std::span<const std::string_view> candidates);
std::string suggestName(std::string_view wrong, EnumTable table);

class StatementReader {
public:
  StatementReader(TokenCursor &cursor, const Token &name, ParameterScope &scope)
      : cursor_(cursor), name_(name), scope_(scope) {}

  const Token &statementToken() const { return name_; }
  const std::string &statementName() const { return name_.text; }

  const Token &peek() const { return cursor_.peek(); }
  const Token &take() { return cursor_.next(); }
  bool atEnd() const;
  bool peekIsNumber() const; // a number, or a reference to a parameter of numbers
  bool peekIsWord(std::string_view word) const;

  // One number; `what` names it in messages ("angle").
  Number number(std::string_view what);
  // A run of min..max numbers (a `$name` counts for as many numbers as the parameter holds).
  // Messages name the statement, or `subject` (a named parameter) when given.
  Numbers numbers(std::string_view what, int min, int max, std::string_view subject = {});
  // A number whose value must be known while parsing (a constant, or an unanimated parameter).
  double constant(std::string_view what);
  int integer(std::string_view what, long long min, long long max);
  GLenumValue word(EnumTable table, std::string_view what);
  bool boolean(std::string_view what); // on/off, true/false, yes/no, 1/0
  std::string string(std::string_view what);
  std::string identifier(std::string_view what);
  // A bracketed list of numbers whose length is a positive multiple of groupSize.
  Numbers list(std::string_view what, int groupSize);
  // A bracketed list of non-negative integers.
  std::vector<std::uint32_t> indexList(std::string_view what);
  // The statement must end here.
  void end();

  [[noreturn]] void fail(const Token &at, std::string message) const;
  [[noreturn]] void fail(SourceLocation at, int length, std::string message) const;

private:
  // Appends the numbers a number token or a reference stands for.
  void appendNumbers(const Token &token, Numbers &out, std::string_view what);

  TokenCursor &cursor_;
  const Token &name_;
  ParameterScope &scope_;
};

// ---- Named parameters ------------------------------------------------------------------------

enum class ParamKind {
  Numbers,   // min..max numbers
  Constant,  // one number known while parsing
  Integer,   // one integer in [min, max]
  Word,      // one name from `table`
  Boolean,
  String,
  List,      // a bracketed list of numbers, in groups of `min`
  IndexList, // a bracketed list of integers
};

struct ParamSpec {
  std::string_view name;
  ParamKind kind = ParamKind::Numbers;
  long long min = 1, max = 1;
  EnumTable table{};
  std::string_view meaning; // for messages: "r g b [a]"
};

struct ParamValue {
  const ParamSpec *spec = nullptr;
  SourceLocation where;
  int length = 1;
  Numbers numbers;
  double constant = 0.0;
  long long integer = 0;
  GLenumValue word = 0;
  bool boolean = false;
  std::string string;
  std::vector<std::uint32_t> indices;
  bool used = false;
};

class NamedParams {
public:
  // Reads `name value...` pairs up to the end of the statement.
  static NamedParams read(StatementReader &reader, std::span<const ParamSpec> specs);

  bool has(std::string_view name) const;
  // The parameter, marked as used, or null when not given.
  const ParamValue *take(std::string_view name);
  // Shortcuts for taken parameters with a default.
  double constantOr(std::string_view name, double fallback);
  long long integerOr(std::string_view name, long long fallback);
  GLenumValue wordOr(std::string_view name, GLenumValue fallback);
  bool booleanOr(std::string_view name, bool fallback);
  Number numberOr(std::string_view name, double fallback);
  // Throws for the first parameter that was given but not used; `context` says why it is not
  // ("with mode exp").
  void requireAllUsed(const StatementReader &reader, std::string_view context = {}) const;

  const std::vector<ParamValue> &values() const { return values_; }

private:
  std::vector<ParamValue> values_;
};

} // namespace glass::scene
