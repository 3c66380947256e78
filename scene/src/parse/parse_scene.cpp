// Scene settings: size, frames, and the parameters that `--set` and `animate` change.
#include "parser_impl.h"

#include <cmath>
#include <cstdlib>

namespace glass::scene {

namespace {

// "1,2,3" or "1 2 3" -> numbers; false on anything else.
bool parseOverrideValue(const std::string &text, std::vector<double> &out) {
  const char *p = text.c_str();
  while (*p != '\0') {
    while (*p == ' ' || *p == ',' || *p == '\t') ++p;
    if (*p == '\0') break;
    char *endPtr = nullptr;
    double value = std::strtod(p, &endPtr);
    if (endPtr == p || !std::isfinite(value)) return false;
    if (*endPtr != '\0' && *endPtr != ' ' && *endPtr != ',' && *endPtr != '\t') return false;
    out.push_back(value);
    p = endPtr;
  }
  return !out.empty();
}

} // namespace

void Parser::parseSize(StatementReader &r) {
  int width = r.integer("width", 1, 16384);
  int height = r.integer("height", 1, 16384);
  r.end();
  if (sizeSeen_) {
    throw StatementError{r.statementToken().where, r.statementToken().length,
                         "'size' is given twice", {{sizeWhere_, "first given here"}}};
  }
  sizeSeen_ = true;
  sizeWhere_ = r.statementToken().where;
  program_.width = width;
  program_.height = height;
}

void Parser::parseFrames(StatementReader &r) {
  int frames = r.integer("the frame count", 1, 100000);
  r.end();
  if (framesSeen_) {
    throw StatementError{r.statementToken().where, r.statementToken().length,
                         "'frames' is given twice", {{framesWhere_, "first given here"}}};
  }
  framesSeen_ = true;
  framesWhere_ = r.statementToken().where;
  program_.frames = frames;
}

void Parser::parseParam(StatementReader &r) {
  const Token &nameToken = r.peek();
  Parameter parameter;
  parameter.name = r.identifier("a parameter name");
  parameter.where = nameToken.where;
  int existing = program_.findParameter(parameter.name);
  if (existing >= 0) {
    throw StatementError{nameToken.where, nameToken.length,
                         "parameter '" + parameter.name + "' is already declared",
                         {{program_.parameters[static_cast<std::size_t>(existing)].where, "first declared here"}}};
  }
  std::size_t count = 0;
  if (r.peekIsWord("rotation")) {
    r.take();
    parameter.kind = Parameter::Kind::Rotation;
    count = 4;
  }
  // The value: constants only (a parameter's value cannot refer to another one).
  while (r.peek().kind == TokenKind::Number) parameter.value.push_back(r.take().number);
  if (parameter.kind == Parameter::Kind::Rotation && parameter.value.size() != 4) {
    r.fail(r.peek(), "a rotation parameter needs 4 numbers (angle in degrees, then axis x y z), found " +
                         std::to_string(parameter.value.size()));
  }
  if (parameter.value.empty()) {
    r.fail(r.peek(), "'param " + parameter.name + "' needs a value: 1 to 16 numbers, or 'rotation ANGLE X Y Z'");
  }
  if (parameter.value.size() > 16) r.fail(r.peek(), "a parameter holds at most 16 numbers");
  count = parameter.value.size();
  r.end();
  // The parameter is declared whatever --set says, so that a bad --set value is one error
  // rather than one more at every use.
  program_.parameters.push_back(parameter);
  Parameter &declared = program_.parameters.back();
  // --set replaces the declared value.
  for (std::size_t i = 0; i < options_.overrides.size(); ++i) {
    if (options_.overrides[i].first != declared.name) continue;
    overrideUsed_[i] = true;
    std::vector<double> value;
    const std::string &text = options_.overrides[i].second;
    if (!parseOverrideValue(text, value)) {
      r.fail(nameToken, "--set " + declared.name + "=" + text + ": the value must be numbers separated by commas");
    }
    if (value.size() != count) {
      r.fail(nameToken, "--set " + declared.name + "=" + text + ": '" + declared.name + "' holds " +
                            std::to_string(count) + (count == 1 ? " number" : " numbers") + ", the value gives " +
                            std::to_string(value.size()));
    }
    declared.value = value;
  }
}

void Parser::parseAnimate(StatementReader &r) {
  const Token &nameToken = r.peek();
  std::string name = r.identifier("the name of a parameter");
  int index = program_.findParameter(name);
  if (index < 0) r.fail(nameToken, "no parameter called '" + name + "': declare it with 'param' first");
  Parameter &parameter = program_.parameters[static_cast<std::size_t>(index)];
  if (!parameter.keys.empty()) {
    throw StatementError{nameToken.where, nameToken.length, "'" + name + "' is already animated",
                         {{parameter.keys.front().where, "its first key is here"}}};
  }
  if (static_cast<std::size_t>(index) < constantUses_.size() && constantUses_[static_cast<std::size_t>(index)].valid()) {
    throw StatementError{nameToken.where, nameToken.length,
                         "'" + name + "' cannot be animated: it is used where a fixed number is needed",
                         {{constantUses_[static_cast<std::size_t>(index)], "used as a fixed number here"}}};
  }
  std::vector<Keyframe> keys;
  while (!r.atEnd()) {
    const Token &keyToken = r.peek();
    if (!r.peekIsWord("key")) {
      r.fail(keyToken, "'animate' expects 'key FRAME VALUE...', found " + describeToken(keyToken));
    }
    r.take();
    Keyframe key;
    key.where = keyToken.where;
    const Token &frameToken = r.peek();
    key.frame = r.integer("the key's frame", 0, 100000);
    if (!keys.empty() && key.frame <= keys.back().frame) {
      r.fail(frameToken, "key frames must increase: " + frameToken.text + " comes after frame " +
                             std::to_string(static_cast<long long>(keys.back().frame)));
    }
    while (r.peek().kind == TokenKind::Number) key.value.push_back(r.take().number);
    if (key.value.size() != parameter.value.size()) {
      r.fail(r.peek(), "each key of '" + name + "' needs " + std::to_string(parameter.value.size()) +
                           (parameter.kind == Parameter::Kind::Rotation ? " numbers (angle x y z)" : " numbers") +
                           ", found " + std::to_string(key.value.size()));
    }
    keys.push_back(std::move(key));
  }
  if (keys.empty()) r.fail(r.peek(), "'animate " + name + "' needs at least one 'key FRAME VALUE...'");
  // A --set value wins over the animation.
  for (const auto &[setName, value] : options_.overrides) {
    if (setName == name) return;
  }
  parameter.keys = std::move(keys);
}

} // namespace glass::scene
