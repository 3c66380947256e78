#include "popup_menu.h"

#include <GL/freeglut.h>

#include <algorithm>
#include <cstring>

#include "glut_state.h"
#include "presentation.h"

namespace glass::glut {

namespace {

// freeglut's menu layout (fg_menu.c): a border of 2 pixels, entries glutBitmapHeight + 2 tall,
// the box as wide as the longest label (plus the width of '_' for a submenu's arrow) and 4
// borders.
constexpr int kBorder = 2;

int entryHeight(const Menu& menu) { return glutBitmapHeight(menu.font) + kBorder; }

struct Box {
  int x, y, width, height;
  bool contains(int px, int py) const {
    return px >= x && px < x + width && py >= y && py < y + height;
  }
};

Box boxSize(const Menu& menu) {
  int width = 0;
  for (const MenuItem& item : menu.items) {
    int itemWidth = glutBitmapLength(menu.font, reinterpret_cast<const unsigned char*>(item.label.c_str()));
    if (item.isSubMenu) itemWidth += glutBitmapWidth(menu.font, '_');
    width = std::max(width, itemWidth);
  }
  return Box{0, 0, width + 4 * kBorder,
             static_cast<int>(menu.items.size()) * entryHeight(menu) + 2 * kBorder};
}

Box boxOf(const OpenMenu& open) {
  const Menu* menu = findMenu(open.menu);
  if (!menu) return Box{open.x, open.y, 0, 0};
  Box box = boxSize(*menu);
  box.x = open.x;
  box.y = open.y;
  return box;
}

// Where a menu of this size goes when asked at (x, y): there if it fits in the window, else
// moved in from the right and bottom edges (from the left of `leftAlternative` for submenus).
void placeInWindow(const Window& window, const Box& size, int& x, int& y, int leftAlternative) {
  if (x + size.width > window.width) x = leftAlternative - size.width;
  if (x < 0) x = std::max(0, window.width - size.width);
  if (y + size.height > window.height) y = window.height - size.height;
  if (y < 0) y = 0;
}

// The entry (0-based) of the open menu at the point, or -1.
int entryAt(const OpenMenu& open, int x, int y) {
  const Menu* menu = findMenu(open.menu);
  const Box box = boxOf(open);
  if (!menu || !box.contains(x, y)) return -1;
  const int inside = y - box.y - kBorder;
  if (inside < 0) return -1;
  const int entry = inside / entryHeight(*menu);
  return entry < static_cast<int>(menu->items.size()) ? entry : -1;
}

void notifyMenuStatus(int status, int x, int y) {
  State& s = state();
  if (s.menuStatus) s.menuStatus(status, x, y);
  if (s.menuState) s.menuState(status);
}

// Opens the submenu of entry `entry` of level `level` beside it, closing deeper levels.
void openSubMenuBeside(Window& window, size_t level, int entry) {
  if (window.openMenus.size() > level + 1) {
    // A submenu closes: what it covered is to be drawn again (as in closePopup).
    window.openMenus.resize(level + 1);
    window.redisplayPending = true;
  }
  const OpenMenu parent = window.openMenus[level];
  const Menu* menu = findMenu(parent.menu);
  if (!menu || entry < 0 || entry >= static_cast<int>(menu->items.size())) return;
  const MenuItem& item = menu->items[static_cast<size_t>(entry)];
  if (!item.isSubMenu || !findMenu(item.value)) return;
  const Box parentBox = boxOf(parent);
  OpenMenu sub;
  sub.menu = item.value;
  sub.x = parentBox.x + parentBox.width;
  sub.y = parentBox.y + entry * entryHeight(*menu);
  placeInWindow(window, boxSize(*findMenu(item.value)), sub.x, sub.y, parentBox.x);
  window.openMenus.push_back(sub);
}

// Runs the callback of the entry's menu with its value, the window and the menu current.
void choose(Window& window, int menuId, int value) {
  const int windowId = window.id;
  closePopup(window);
  State& s = state();
  Menu* menu = findMenu(menuId);
  if (!menu || !menu->callback) return;
  const int previousMenu = s.currentMenu;
  if (Window* still = findWindow(windowId)) makeCurrent(*still);
  s.currentMenu = menuId;
  menu->callback(value);
  if (findMenu(previousMenu)) s.currentMenu = previousMenu;
}

// Picks entry `entry` of level `level`: a submenu opens, an entry is chosen.
void pick(Window& window, size_t level, int entry) {
  const OpenMenu open = window.openMenus[level];
  const Menu* menu = findMenu(open.menu);
  if (!menu) return;
  const MenuItem& item = menu->items[static_cast<size_t>(entry)];
  if (item.isSubMenu) {
    window.openMenus[level].highlighted = entry;
    openSubMenuBeside(window, level, entry);
    refreshScreen(window);
    return;
  }
  choose(window, open.menu, item.value);
}

void drawBox(const Menu& menu, const OpenMenu& open) {
  const Box box = boxOf(open);
  const int x0 = box.x, y0 = box.y, x1 = box.x + box.width, y1 = box.y + box.height;
  // A raised bevel: light on the top and left, dark on the bottom and right, as freeglut's.
  glColor3f(1.0f, 1.0f, 1.0f);
  glRecti(x0, y0, x1, y1);
  glColor3f(0.5f, 0.5f, 0.5f);
  glRecti(x0 + kBorder, y0 + kBorder, x1, y1);
  glColor3f(0.7f, 0.7f, 0.7f);
  glRecti(x0 + kBorder, y0 + kBorder, x1 - kBorder, y1 - kBorder);

  const int height = entryHeight(menu);
  if (open.highlighted >= 0) {
    glColor3f(1.0f, 1.0f, 1.0f);
    const int top = y0 + kBorder + open.highlighted * height;
    glRecti(x0 + kBorder, top, x1 - kBorder, top + height);
  }
  glColor3f(0.0f, 0.0f, 0.0f);
  for (size_t i = 0; i < menu.items.size(); ++i) {
    const MenuItem& item = menu.items[i];
    const int top = y0 + kBorder + static_cast<int>(i) * height;
    // The baseline about a third of the entry above its bottom, as freeglut places it.
    glRasterPos2i(x0 + 2 * kBorder, top + height - (height * 3 / 10 - kBorder));
    glutBitmapString(menu.font, reinterpret_cast<const unsigned char*>(item.label.c_str()));
    if (item.isSubMenu) {
      const int arrowLeft = x1 - kBorder - glutBitmapWidth(menu.font, '_');
      glBegin(GL_TRIANGLES);
      glVertex2i(arrowLeft, top + 2 * kBorder);
      glVertex2i(x1 - kBorder, top + (height + kBorder) / 2);
      glVertex2i(arrowLeft, top + height - kBorder);
      glEnd();
    }
  }
}

}  // namespace

void openPopup(Window& window, int menuId, int button, int x, int y) {
  const Menu* menu = findMenu(menuId);
  if (!menu) return;
  OpenMenu open;
  open.menu = menuId;
  open.x = x;
  open.y = y;
  placeInWindow(window, boxSize(*menu), open.x, open.y, x);
  window.openMenus.assign(1, open);
  window.menuButton = button;
  window.popupOpenedAtX = x;
  window.popupOpenedAtY = y;
  notifyMenuStatus(GLUT_MENU_IN_USE, x, y);
  refreshScreen(window);
}

void closePopup(Window& window) {
  if (window.openMenus.empty()) return;
  window.openMenus.clear();
  window.menuButton = -1;
  // The window is drawn again where the pop-up was, as with freeglut and GLUT 3.7 on X, whose
  // pop-ups are windows of their own: taking one away exposes the program's window, whose
  // display callback then runs (once, with any glutPostRedisplay of the menu's callback).
  window.redisplayPending = true;
  notifyMenuStatus(GLUT_MENU_NOT_IN_USE, window.mouseX, window.mouseY);
  if (findWindow(window.id)) refreshScreen(window);
}

bool popupTakesButton(Window& window, int button, int buttonState, int x, int y) {
  if (window.openMenus.empty()) return false;
  for (size_t level = window.openMenus.size(); level-- > 0;) {
    const int entry = entryAt(window.openMenus[level], x, y);
    if (entry >= 0) {
      if (buttonState == GLUT_UP) pick(window, level, entry);
      return true;
    }
    if (boxOf(window.openMenus[level]).contains(x, y)) return true;  // on the border
  }
  // A release where the pop-up opened (a click rather than a drag) leaves it open, to be picked
  // with a second click; a press or release anywhere else outside it closes it.
  const bool clickThatOpened = buttonState == GLUT_UP && button == window.menuButton &&
                               x == window.popupOpenedAtX && y == window.popupOpenedAtY;
  if (!clickThatOpened) closePopup(window);
  return true;
}

void popupFollowPointer(Window& window, int x, int y) {
  for (size_t level = window.openMenus.size(); level-- > 0;) {
    const int entry = entryAt(window.openMenus[level], x, y);
    if (entry < 0) continue;
    OpenMenu& open = window.openMenus[level];
    if (open.highlighted == entry && window.openMenus.size() > level + 1) return;
    open.highlighted = entry;
    openSubMenuBeside(window, level, entry);  // closes the deeper levels, opens a submenu
    refreshScreen(window);
    return;
  }
  OpenMenu& deepest = window.openMenus.back();
  if (deepest.highlighted >= 0) {
    deepest.highlighted = -1;
    refreshScreen(window);
  }
}

bool popupChooseEntry(Window& window, int index, std::string& error) {
  if (window.openMenus.empty()) {
    error = "no pop-up menu is open";
    return false;
  }
  const size_t level = window.openMenus.size() - 1;
  const Menu* menu = findMenu(window.openMenus[level].menu);
  if (!menu || index < 0 || index >= static_cast<int>(menu->items.size())) {
    error = "the menu has " + std::to_string(menu ? menu->items.size() : 0) + " entries, not " +
            std::to_string(index + 1);
    return false;
  }
  pick(window, level, index);
  return true;
}

void drawPopupOverPicture(Window& window) {
  if (!window.menuContext) {
    window.menuContext = glassCreateContext(window.width, window.height);
  } else if (glassGetWidth(window.menuContext) != window.width ||
             glassGetHeight(window.menuContext) != window.height) {
    glassResizeContext(window.menuContext, window.width, window.height);
  }
  if (!window.menuContext) return;  // out of memory: the picture without the pop-up
  GlassContext* previous = glassGetCurrentContext();
  glassMakeCurrent(window.menuContext);
  glViewport(0, 0, window.width, window.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  // Window coordinates with y down, as the pointer's; pixel centres at half-integers.
  glOrtho(0, window.width, window.height, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(window.width, window.height, GL_RGBA, GL_UNSIGNED_BYTE, window.screen.data());
  for (const OpenMenu& open : window.openMenus) {
    if (const Menu* menu = findMenu(open.menu)) drawBox(*menu, open);
  }
  const unsigned char* pixels = glassGetColorBuffer(window.menuContext);
  window.screen.assign(pixels, pixels + static_cast<size_t>(window.width) * window.height * 4);
  glassMakeCurrent(previous);
}

}  // namespace glass::glut
