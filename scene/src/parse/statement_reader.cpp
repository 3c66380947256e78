#include "statement_reader.h"

#include <algorithm>
#include <cmath>

namespace glass::scene {

namespace {

std::string plural(long long n, std::string_view noun) {
  return std::to_string(n) + " " + std::string(noun) + (n == 1 ? "" : "s");
}

std::string withMeaning(std::string_view what) {
  return what.empty() ? std::string() : " (" + std::string(what) + ")";
}

// Edit distance with transpositions (optimal string alignment), for suggestions: a swapped
// pair of letters ("sclae") counts as one slip, like a missing or a wrong letter.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

} // namespace

const Token &TokenCursor::next() {
  const Token &token = tokens_[index_];
  if (token.kind != TokenKind::EndOfFile) ++index_;
  return token;
}

void TokenCursor::skipStatement() {
  while (true) {
    const Token &token = tokens_[index_];
    if (token.kind == TokenKind::EndOfFile) return;
    ++index_;
    if (token.kind == TokenKind::EndOfLine) return;
  }
}

SourceLocation TokenCursor::statementEnd() const {
  for (std::size_t i = index_; i < tokens_.size(); ++i) {
    TokenKind kind = tokens_[i].kind;
    if (kind == TokenKind::EndOfLine || kind == TokenKind::EndOfFile) return tokens_[i].where;
  }
  return tokens_.back().where;
}

std::string suggestName(std::string_view wrong, std::span<const std::string_view> candidates) {
  std::string_view best;
  std::size_t bestDistance = 0;
  for (std::string_view candidate : candidates) {
    std::size_t d = editDistance(wrong, candidate);
    if (best.empty() || d < bestDistance) {
      best = candidate;
      bestDistance = d;
    }
  }
  // Close enough to be a typing slip: at most a third of the word, and at most 3 edits.
  std::size_t allowed = std::min<std::size_t>(3, std::max<std::size_t>(1, wrong.size() / 3));
  if (best.empty() || bestDistance > allowed) return {};
  return "did you mean '" + std::string(best) + "'?";
}

std::string suggestName(std::string_view wrong, EnumTable table) {
  std::vector<std::string_view> candidates;
  for (const EnumName &entry : table) candidates.push_back(entry.name);
  return suggestName(wrong, candidates);
}

// ---- StatementReader -------------------------------------------------------------------------

bool StatementReader::atEnd() const {
  TokenKind kind = peek().kind;
  return kind == TokenKind::EndOfLine || kind == TokenKind::EndOfFile;
}

bool StatementReader::peekIsNumber() const {
  // A reference counts as a number here; appendNumbers says so when it names a rotation.
  TokenKind kind = peek().kind;
  return kind == TokenKind::Number || kind == TokenKind::Reference;
}

bool StatementReader::peekIsWord(std::string_view word) const {
  return peek().kind == TokenKind::Word && peek().text == word;
}

void StatementReader::fail(const Token &at, std::string message) const {
  throw StatementError{at.where, at.length, std::move(message), {}};
}

void StatementReader::fail(SourceLocation at, int length, std::string message) const {
  throw StatementError{at, length, std::move(message), {}};
}

void StatementReader::appendNumbers(const Token &token, Numbers &out, std::string_view what) {
  if (token.kind == TokenKind::Number) {
    out.push_back(Number::of(token.number));
    return;
  }
  if (token.kind == TokenKind::Reference) {
    int index = 0;
    Parameter *parameter = scope_.findParameter(token.text, index);
    if (parameter == nullptr) {
      fail(token, "unknown parameter '$" + token.text + "': declare it first with 'param " +
                      token.text + " ...'");
    }
    if (parameter->kind == Parameter::Kind::Rotation) {
      fail(token, "'$" + token.text + "' is a rotation; only 'rotate' takes it");
    }
    for (std::size_t c = 0; c < parameter->value.size(); ++c) {
      out.push_back(Number{parameter->value[c], index, static_cast<int>(c)});
    }
    return;
  }
  fail(token, "'" + statementName() + "' expects " + std::string(what.empty() ? "a number" : what) +
                  " here, found " + describeToken(token));
}

Number StatementReader::number(std::string_view what) {
  const Token &token = peek();
  if (token.kind != TokenKind::Number && token.kind != TokenKind::Reference) {
    fail(token, "'" + statementName() + "' expects a number" + withMeaning(what) + ", found " +
                    describeToken(token));
  }
  Numbers values;
  appendNumbers(take(), values, what);
  if (values.size() != 1) {
    fail(token, "'$" + token.text + "' holds " + plural(static_cast<long long>(values.size()), "number") +
                    " but " + std::string(what.empty() ? "this value" : what) + " is one number");
  }
  return values[0];
}

Numbers StatementReader::numbers(std::string_view what, int min, int max, std::string_view subject) {
  std::string owner(1, '\'');
  owner += subject.empty() ? std::string_view(statementName()) : subject;
  owner += '\'';
  Numbers values;
  while (peekIsNumber()) {
    const Token &token = take();
    std::size_t before = values.size();
    appendNumbers(token, values, what);
    if (static_cast<int>(values.size()) > max) {
      if (before == static_cast<std::size_t>(max) || token.kind == TokenKind::Number) {
        fail(token, "too many numbers for " + owner + ": it takes " +
                        (min == max ? std::to_string(max) : "at most " + std::to_string(max)) + withMeaning(what));
      }
      fail(token, "'$" + token.text + "' gives " +
                      plural(static_cast<long long>(values.size() - before), "number") +
                      ", more than fit here" + withMeaning(what));
    }
  }
  if (static_cast<int>(values.size()) < min) {
    std::string needed = min == max ? std::to_string(min) : "at least " + std::to_string(min);
    std::string found = values.empty() ? "found " + describeToken(peek())
                        : atEnd()      ? "found only " + std::to_string(values.size())
                                       : "found " + describeToken(peek()) + " after " + std::to_string(values.size());
    fail(peek(), owner + " needs " + needed + " number" + (min == 1 ? "" : "s") + withMeaning(what) + ", " + found);
  }
  return values;
}

double StatementReader::constant(std::string_view what) {
  const Token &token = peek();
  if (token.kind == TokenKind::Reference) {
    int index = 0;
    Parameter *parameter = scope_.findParameter(token.text, index);
    if (parameter != nullptr && parameter->kind == Parameter::Kind::Numbers &&
        parameter->value.size() == 1) {
      // 'animate' before this use; an 'animate' after it reports the use (parseAnimate).
      if (!parameter->keys.empty()) {
        throw StatementError{token.where, token.length,
                             "'$" + token.text + "' is animated, but " + std::string(what) +
                                 " must be a fixed number, known while reading the scene",
                             {{parameter->keys.front().where, "it is animated from here"}}};
      }
      take();
      scope_.noteConstantUse(index, token.where);
      return parameter->value[0];
    }
  }
  Number n = number(what);
  return n.constant;
}

int StatementReader::integer(std::string_view what, long long min, long long max) {
  const Token &token = peek();
  double value = constant(what);
  if (value != std::floor(value)) {
    fail(token, std::string(what) + " must be a whole number, not " + token.text);
  }
  if (value < static_cast<double>(min) || value > static_cast<double>(max)) {
    std::string shown = token.kind == TokenKind::Number ? token.text : std::to_string(static_cast<long long>(value));
    fail(token, std::string(what) + " must be between " + std::to_string(min) + " and " +
                    std::to_string(max) + ", not " + shown);
  }
  return static_cast<int>(value);
}

GLenumValue StatementReader::word(EnumTable table, std::string_view what) {
  const Token &token = peek();
  if (token.kind != TokenKind::Word) {
    fail(token, "'" + statementName() + "' expects " + std::string(what) + " (" + listNames(table) +
                    "), found " + describeToken(token));
  }
  GLenumValue value = 0;
  if (!lookupEnum(table, token.text, value)) {
    std::string hint = suggestName(token.text, table);
    fail(token, "unknown " + std::string(what) + " '" + token.text + "'; " +
                    (hint.empty() ? "expected " + listNames(table) : hint));
  }
  take();
  return value;
}

bool StatementReader::boolean(std::string_view what) {
  const Token &token = peek();
  if (token.kind == TokenKind::Number && (token.number == 0.0 || token.number == 1.0)) {
    take();
    return token.number == 1.0;
  }
  if (token.kind == TokenKind::Word) {
    const std::string &t = token.text;
    if (t == "on" || t == "true" || t == "yes") return take(), true;
    if (t == "off" || t == "false" || t == "no") return take(), false;
  }
  fail(token, std::string(what) + " must be on or off (also true/false, yes/no, 1/0), found " +
                  describeToken(token));
}

std::string StatementReader::string(std::string_view what) {
  const Token &token = peek();
  if (token.kind != TokenKind::String) {
    fail(token, "'" + statementName() + "' expects " + std::string(what) +
                    " as a quoted string, found " + describeToken(token));
  }
  return take().text;
}

std::string StatementReader::identifier(std::string_view what) {
  const Token &token = peek();
  if (token.kind != TokenKind::Word) {
    fail(token, "'" + statementName() + "' expects " + std::string(what) + ", found " +
                    describeToken(token));
  }
  return take().text;
}

Numbers StatementReader::list(std::string_view what, int groupSize) {
  const Token &open = peek();
  if (open.kind != TokenKind::ListOpen) {
    fail(open, std::string(what) + " must be a list in brackets [ ... ], found " + describeToken(open));
  }
  take();
  Numbers values;
  while (peek().kind != TokenKind::ListClose) {
    const Token &token = peek();
    if (token.kind == TokenKind::EndOfFile || token.kind == TokenKind::EndOfLine) {
      fail(token, "list is not closed: ']' expected");
    }
    appendNumbers(take(), values, what);
  }
  const Token &close = take();
  if (values.empty()) fail(close, std::string(what) + " is an empty list");
  if (values.size() % static_cast<std::size_t>(groupSize) != 0) {
    fail(open.where, close.where.line == open.where.line ? close.where.column - open.where.column + 1 : 1,
         std::string(what) + " holds " + plural(static_cast<long long>(values.size()), "number") +
             ", not a multiple of " + std::to_string(groupSize));
  }
  return values;
}

std::vector<std::uint32_t> StatementReader::indexList(std::string_view what) {
  const Token &open = peek();
  if (open.kind != TokenKind::ListOpen) {
    fail(open, std::string(what) + " must be a list in brackets [ ... ], found " + describeToken(open));
  }
  take();
  std::vector<std::uint32_t> values;
  while (peek().kind != TokenKind::ListClose) {
    const Token &token = peek();
    if (token.kind != TokenKind::Number) {
      if (token.kind == TokenKind::EndOfFile || token.kind == TokenKind::EndOfLine) {
        fail(token, "list is not closed: ']' expected");
      }
      fail(token, std::string(what) + " holds whole numbers only, found " + describeToken(token));
    }
    if (token.number < 0 || token.number != std::floor(token.number) || token.number > 4294967295.0) {
      fail(token, std::string(what) + " must be whole numbers from 0, not " + token.text);
    }
    values.push_back(static_cast<std::uint32_t>(token.number));
    take();
  }
  const Token &close = take();
  if (values.empty()) fail(close, std::string(what) + " is an empty list");
  return values;
}

void StatementReader::end() {
  if (!atEnd()) {
    fail(peek(), "unexpected " + describeToken(peek()) + " at the end of '" + statementName() + "'");
  }
}

// ---- NamedParams -----------------------------------------------------------------------------

NamedParams NamedParams::read(StatementReader &reader, std::span<const ParamSpec> specs) {
  NamedParams result;
  while (!reader.atEnd()) {
    const Token &nameToken = reader.peek();
    if (nameToken.kind != TokenKind::Word) {
      std::string known;
      for (std::size_t i = 0; i < specs.size(); ++i) known += (i ? ", " : "") + std::string(specs[i].name);
      reader.fail(nameToken, "expected a parameter name of '" + reader.statementName() + "' (" +
                                 (known.empty() ? "it has none" : known) + "), found " +
                                 describeToken(nameToken));
    }
    const ParamSpec *spec = nullptr;
    for (const ParamSpec &candidate : specs) {
      if (candidate.name == nameToken.text) spec = &candidate;
    }
    if (spec == nullptr) {
      std::vector<std::string_view> names;
      for (const ParamSpec &candidate : specs) names.push_back(candidate.name);
      std::string hint = suggestName(nameToken.text, names);
      std::string known;
      for (std::size_t i = 0; i < names.size(); ++i) known += (i ? ", " : "") + std::string(names[i]);
      reader.fail(nameToken, "unknown parameter '" + nameToken.text + "' for '" + reader.statementName() +
                                 "'; " + (hint.empty() ? (known.empty() ? "it takes none" : "known: " + known) : hint));
    }
    for (const ParamValue &earlier : result.values_) {
      if (earlier.spec == spec) {
        throw StatementError{nameToken.where, nameToken.length,
                             "parameter '" + nameToken.text + "' is given twice",
                             {{earlier.where, "first given here"}}};
      }
    }
    reader.take();
    ParamValue value;
    value.spec = spec;
    value.where = nameToken.where;
    value.length = nameToken.length;
    std::string what(spec->meaning.empty() ? spec->name : spec->meaning);
    switch (spec->kind) {
    case ParamKind::Numbers:
      value.numbers = reader.numbers(spec->meaning, static_cast<int>(spec->min), static_cast<int>(spec->max),
                                     spec->name);
      break;
    case ParamKind::Constant: value.constant = reader.constant(spec->name); break;
    case ParamKind::Integer: value.integer = reader.integer(spec->name, spec->min, spec->max); break;
    case ParamKind::Word: value.word = reader.word(spec->table, spec->name); break;
    case ParamKind::Boolean: value.boolean = reader.boolean(spec->name); break;
    case ParamKind::String: value.string = reader.string(spec->name); break;
    case ParamKind::List: value.numbers = reader.list(spec->name, static_cast<int>(spec->min)); break;
    case ParamKind::IndexList: value.indices = reader.indexList(spec->name); break;
    }
    result.values_.push_back(std::move(value));
  }
  return result;
}

bool NamedParams::has(std::string_view name) const {
  return std::any_of(values_.begin(), values_.end(),
                     [&](const ParamValue &v) { return v.spec->name == name; });
}

const ParamValue *NamedParams::take(std::string_view name) {
  for (ParamValue &v : values_) {
    if (v.spec->name == name) {
      v.used = true;
      return &v;
    }
  }
  return nullptr;
}

double NamedParams::constantOr(std::string_view name, double fallback) {
  const ParamValue *v = take(name);
  return v ? v->constant : fallback;
}

long long NamedParams::integerOr(std::string_view name, long long fallback) {
  const ParamValue *v = take(name);
  return v ? v->integer : fallback;
}

GLenumValue NamedParams::wordOr(std::string_view name, GLenumValue fallback) {
  const ParamValue *v = take(name);
  return v ? v->word : fallback;
}

bool NamedParams::booleanOr(std::string_view name, bool fallback) {
  const ParamValue *v = take(name);
  return v ? v->boolean : fallback;
}

Number NamedParams::numberOr(std::string_view name, double fallback) {
  const ParamValue *v = take(name);
  return v ? v->numbers.at(0) : Number::of(fallback);
}

void NamedParams::requireAllUsed(const StatementReader &reader, std::string_view context) const {
  for (const ParamValue &v : values_) {
    if (!v.used) {
      std::string message = "parameter '" + std::string(v.spec->name) + "' is not used by '" +
                            reader.statementName() + "'";
      if (!context.empty()) {
        message += ' ';
        message += context;
      }
      reader.fail(v.where, v.length, message);
    }
  }
}

} // namespace glass::scene
