// The events file of GLASS_GLUT_EVENTS (docs/glut.md): one event per line, replayed in order.
//   key C               a key pressed and released: a character (`key r`, `key R`), or space,
//                       escape, enter, tab, backspace, delete; ctrl+, shift+, alt+ before it
//   special NAME        f1..f12, left, up, right, down, page_up, page_down, home, end, insert
//   mouse BUTTON down|up X Y   BUTTON: left, middle, right (modifiers as for key)
//   motion X Y          the pointer moves (dragging while a button is down)
//   wheel up|down X Y   the mouse wheel, one step
//   menu I [J ...]      entry I (from 1) of the open pop-up menu, or of the right button's menu
//                       when none is open, then entry J of the submenu it opens, ...
//   reshape W H         the window is resized
//   close               the window manager's close button
//   wait MS             the next line waits MS milliseconds (the clock is virtual when headless)
//   snapshot FILE       writes what the window shows now
//   window N            the following lines go to window N
// Blank lines and lines starting with # are skipped.
#pragma once

#include <string>
#include <vector>

#include "input_event.h"

namespace glass::glut {

enum class ScriptAction { Input, Menu, Reshape, Close, Wait, Snapshot, SelectWindow };

struct ScriptLine {
  int line = 0;
  ScriptAction action = ScriptAction::Input;
  std::vector<InputEvent> events;  // Input: with window 0, given the target window when run
  std::vector<int> menuPath;       // Menu: 0-based entries
  int width = 0, height = 0;       // Reshape
  int number = 0;                  // Wait: milliseconds; SelectWindow: the window
  std::string path;                // Snapshot
};

// Reads the file; false with "file:line:col: message" in `error` on the first bad line.
bool readEventScript(const std::string& path, std::vector<ScriptLine>& lines, std::string& error);

}  // namespace glass::glut
