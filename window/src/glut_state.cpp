#include "glut_state.h"

namespace glass::glut {

State& state() {
  static State instance;
  return instance;
}

Window* findWindow(int id) {
  auto found = state().windows.find(id);
  return found == state().windows.end() ? nullptr : found->second.get();
}

Window* currentWindow() { return findWindow(state().currentWindow); }

Menu* findMenu(int id) {
  auto found = state().menus.find(id);
  return found == state().menus.end() ? nullptr : found->second.get();
}

void destroyMenu(int id) {
  State& s = state();
  Menu* menu = findMenu(id);
  if (!menu) return;
  if (void (*destroy)() = menu->destroy) {
    menu->destroy = nullptr;
    const int previous = s.currentMenu;
    s.currentMenu = id;
    destroy();
    s.currentMenu = previous;
  }
  s.menus.erase(id);
  if (s.currentMenu == id) s.currentMenu = 0;
}

void makeCurrent(Window& window) {
  state().currentWindow = window.id;
  glassMakeCurrent(window.context);
}

void originInTopLevel(const Window& window, int& x, int& y) {
  x = y = 0;
  for (const Window* w = &window; w->parent != 0;) {
    x += w->x;
    y += w->y;
    w = findWindow(w->parent);
    if (!w) break;
  }
}

Window& topLevelOf(Window& window) {
  Window* top = &window;
  while (Window* parent = findWindow(top->parent)) top = parent;
  return *top;
}

}  // namespace glass::glut
