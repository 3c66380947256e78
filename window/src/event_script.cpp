#include "event_script.h"

#include <GL/freeglut.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>

namespace glass::glut {

namespace {

struct Token {
  std::string text;
  int column = 0;  // 1-based
};

std::vector<Token> tokensOf(const std::string& line) {
  std::vector<Token> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    tokens.push_back(Token{line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return tokens;
}

// A problem at a token: the message carries its column.
struct ScriptError : std::runtime_error {
  int column;
  ScriptError(int column, const std::string& message) : std::runtime_error(message), column(column) {}
};

// "expected WHAT, not 'TOKEN'"
ScriptError expected(const std::string& what, const Token& token) {
  std::string message = "expected ";
  message += what;
  message += ", not '";
  message += token.text;
  message += "'";
  return ScriptError(token.column, message);
}

int numberOf(const Token& token, int minimum, const char* what) {
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(token.text.c_str(), &end, 10);
  if (token.text.empty() || *end != '\0' || errno != 0 || value < minimum || value > 1000000000) {
    throw expected(what, token);
  }
  return static_cast<int>(value);
}

// "ctrl+shift+x" -> modifiers and "x".
std::string takeModifiers(const Token& token, int& modifiers) {
  std::string rest = token.text;
  static const std::map<std::string, int> names = {
      {"ctrl+", GLUT_ACTIVE_CTRL}, {"shift+", GLUT_ACTIVE_SHIFT}, {"alt+", GLUT_ACTIVE_ALT}};
  for (bool found = true; found;) {
    found = false;
    for (const auto& [prefix, bit] : names) {
      if (rest.size() > prefix.size() && rest.compare(0, prefix.size(), prefix) == 0) {
        modifiers |= bit;
        rest.erase(0, prefix.size());
        found = true;
      }
    }
  }
  return rest;
}

int characterOf(const Token& token, int& modifiers) {
  const std::string name = takeModifiers(token, modifiers);
  static const std::map<std::string, int> named = {
      {"space", ' '},    {"escape", 27}, {"esc", 27},      {"enter", 13},
      {"return", 13},    {"tab", 9},     {"backspace", 8}, {"delete", 127}};
  int character = -1;
  if (auto found = named.find(name); found != named.end()) {
    character = found->second;
  } else if (name.size() == 1) {
    character = static_cast<unsigned char>(name[0]);
    if (character >= 'A' && character <= 'Z') modifiers |= GLUT_ACTIVE_SHIFT;
  } else {
    throw expected("a character or space, escape, enter, tab, backspace, delete", token);
  }
  // With Ctrl a letter is a control character, as the X server gives it.
  if ((modifiers & GLUT_ACTIVE_CTRL) && std::isalpha(character)) character &= 0x1f;
  return character;
}

int specialKeyOf(const Token& token, int& modifiers) {
  const std::string name = takeModifiers(token, modifiers);
  static const std::map<std::string, int> named = {
      {"left", GLUT_KEY_LEFT},         {"up", GLUT_KEY_UP},
      {"right", GLUT_KEY_RIGHT},       {"down", GLUT_KEY_DOWN},
      {"page_up", GLUT_KEY_PAGE_UP},   {"pageup", GLUT_KEY_PAGE_UP},
      {"page_down", GLUT_KEY_PAGE_DOWN}, {"pagedown", GLUT_KEY_PAGE_DOWN},
      {"home", GLUT_KEY_HOME},         {"end", GLUT_KEY_END},
      {"insert", GLUT_KEY_INSERT},     {"num_lock", GLUT_KEY_NUM_LOCK},
      {"begin", GLUT_KEY_BEGIN}};
  if (auto found = named.find(name); found != named.end()) return found->second;
  if (name.size() >= 2 && name[0] == 'f') {
    const int number = std::atoi(name.c_str() + 1);
    if (number >= 1 && number <= 12 && name.substr(1) == std::to_string(number)) {
      return GLUT_KEY_F1 + number - 1;
    }
  }
  throw expected("a special key (f1..f12, left, up, right, down, page_up, page_down, home, end, "
                 "insert)",
                 token);
}

int buttonOf(const Token& token, int& modifiers) {
  const std::string name = takeModifiers(token, modifiers);
  if (name == "left") return GLUT_LEFT_BUTTON;
  if (name == "middle") return GLUT_MIDDLE_BUTTON;
  if (name == "right") return GLUT_RIGHT_BUTTON;
  throw expected("left, middle or right", token);
}

void requireCount(const std::vector<Token>& tokens, size_t count, const char* usage) {
  if (tokens.size() != count) {
    const int column = tokens.size() > count ? tokens[count].column : tokens.back().column;
    throw ScriptError(column, std::string("expected '") + usage + "'");
  }
}

ScriptLine parseLine(const std::vector<Token>& t) {
  ScriptLine line;
  const std::string& verb = t[0].text;
  InputEvent event;
  if (verb == "key") {
    requireCount(t, 2, "key CHARACTER");
    event.key = characterOf(t[1], event.modifiers);
    event.kind = InputKind::Key;
    line.events.push_back(event);
    event.kind = InputKind::KeyUp;
    line.events.push_back(event);
  } else if (verb == "special") {
    requireCount(t, 2, "special NAME");
    event.key = specialKeyOf(t[1], event.modifiers);
    event.kind = InputKind::Special;
    line.events.push_back(event);
    event.kind = InputKind::SpecialUp;
    line.events.push_back(event);
  } else if (verb == "mouse") {
    requireCount(t, 5, "mouse BUTTON down|up X Y");
    event.kind = InputKind::Button;
    event.button = buttonOf(t[1], event.modifiers);
    if (t[2].text != "down" && t[2].text != "up") {
      throw expected("down or up", t[2]);
    }
    event.buttonState = t[2].text == "down" ? GLUT_DOWN : GLUT_UP;
    event.x = numberOf(t[3], -100000, "a number");
    event.y = numberOf(t[4], -100000, "a number");
    line.events.push_back(event);
  } else if (verb == "motion") {
    requireCount(t, 3, "motion X Y");
    event.kind = InputKind::Motion;
    event.x = numberOf(t[1], -100000, "a number");
    event.y = numberOf(t[2], -100000, "a number");
    line.events.push_back(event);
  } else if (verb == "wheel") {
    requireCount(t, 4, "wheel up|down X Y");
    if (t[1].text != "up" && t[1].text != "down") {
      throw expected("up or down", t[1]);
    }
    event.kind = InputKind::Wheel;
    event.buttonState = t[1].text == "up" ? 1 : -1;
    event.x = numberOf(t[2], -100000, "a number");
    event.y = numberOf(t[3], -100000, "a number");
    line.events.push_back(event);
  } else if (verb == "menu") {
    if (t.size() < 2) throw ScriptError(t[0].column, "expected 'menu ENTRY [ENTRY ...]'");
    line.action = ScriptAction::Menu;
    for (size_t i = 1; i < t.size(); ++i) {
      line.menuPath.push_back(numberOf(t[i], 1, "an entry number from 1") - 1);
    }
  } else if (verb == "reshape") {
    requireCount(t, 3, "reshape WIDTH HEIGHT");
    line.action = ScriptAction::Reshape;
    line.width = numberOf(t[1], 1, "a width from 1");
    line.height = numberOf(t[2], 1, "a height from 1");
  } else if (verb == "close") {
    requireCount(t, 1, "close");
    line.action = ScriptAction::Close;
  } else if (verb == "wait") {
    requireCount(t, 2, "wait MILLISECONDS");
    line.action = ScriptAction::Wait;
    line.number = numberOf(t[1], 0, "milliseconds");
  } else if (verb == "snapshot") {
    requireCount(t, 2, "snapshot FILE");
    line.action = ScriptAction::Snapshot;
    line.path = t[1].text;
  } else if (verb == "window") {
    requireCount(t, 2, "window NUMBER");
    line.action = ScriptAction::SelectWindow;
    line.number = numberOf(t[1], 1, "a window number from 1");
  } else {
    throw expected("an event (key, special, mouse, motion, wheel, menu, reshape, close, wait, "
                   "snapshot, window)",
                   t[0]);
  }
  return line;
}

}  // namespace

bool readEventScript(const std::string& path, std::vector<ScriptLine>& lines, std::string& error) {
  std::ifstream file(path);
  if (!file) {
    error = path + ": cannot open the events file (" + std::strerror(errno) + ")";
    return false;
  }
  std::string text;
  for (int number = 1; std::getline(file, text); ++number) {
    const std::vector<Token> tokens = tokensOf(text);
    if (tokens.empty() || tokens[0].text[0] == '#') continue;
    try {
      ScriptLine line = parseLine(tokens);
      line.line = number;
      lines.push_back(std::move(line));
    } catch (const ScriptError& e) {
      error = path + ":" + std::to_string(number) + ":" + std::to_string(e.column) + ": " + e.what();
      return false;
    }
  }
  return true;
}

}  // namespace glass::glut
