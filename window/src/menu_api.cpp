// Menus (GLUT 3.7 spec 6): building them, and attaching them to mouse buttons. Items are numbered
// from 1 in the order they were added, as glutChangeToMenuEntry and glutRemoveMenuItem count them.
#include <GL/freeglut.h>

#include <cstdint>
#include <memory>

#include "glut_errors.h"
#include "glut_state.h"
#include "popup_menu.h"

using namespace glass::glut;

namespace {

// freeglut ignores menu calls with no current menu silently; glass says so.
Menu* requireCurrentMenu(const char* function) {
  requireInitialised(function);
  Menu* menu = findMenu(state().currentMenu);
  if (!menu) warning("%s called with no current menu; ignored", function);
  return menu;
}

MenuItem* itemOf(Menu& menu, int item, const char* function) {
  if (item < 1 || item > static_cast<int>(menu.items.size())) {
    warning("%s: menu %d has no item %d", function, menu.id, item);
    return nullptr;
  }
  return &menu.items[static_cast<size_t>(item - 1)];
}

// A pop-up in use shows the menus as they were when it opened; any change closes it first.
void closePopupsShowing(int menu) {
  for (auto& [id, window] : state().windows) {
    for (const OpenMenu& open : window->openMenus) {
      if (open.menu == menu) {
        closePopup(*window);
        break;
      }
    }
  }
}

int requireButton(int button, const char* function) {
  if (button < 0 || button > 4) {
    warning("%s: there is no mouse button %d", function, button);
    return -1;
  }
  return button;
}

}  // namespace

extern "C" {

int glutCreateMenu(void (*callback)(int menu)) {
  requireInitialised("glutCreateMenu");
  State& s = state();
  auto menu = std::make_unique<Menu>();
  menu->id = s.nextMenuId++;
  menu->callback = callback;
  menu->font = GLUT_BITMAP_HELVETICA_18;  // freeglut's menu font on X11
  const int id = menu->id;
  s.menus[id] = std::move(menu);
  s.currentMenu = id;
  return id;
}

void glutDestroyMenu(int id) {
  requireInitialised("glutDestroyMenu");
  State& s = state();
  if (!findMenu(id)) return;
  closePopupsShowing(id);
  destroyMenu(id);
  for (auto& [windowId, window] : s.windows) {
    for (int& attached : window->menuOnButton) {
      if (attached == id) attached = 0;
    }
  }
}

int glutGetMenu(void) {
  requireInitialised("glutGetMenu");
  return findMenu(state().currentMenu) ? state().currentMenu : 0;
}

// freeglut ignores a menu that does not exist.
void glutSetMenu(int id) {
  requireInitialised("glutSetMenu");
  if (findMenu(id)) state().currentMenu = id;
}

void glutAddMenuEntry(const char* label, int value) {
  Menu* menu = requireCurrentMenu("glutAddMenuEntry");
  if (!menu) return;
  closePopupsShowing(menu->id);
  menu->items.push_back(MenuItem{label ? label : "", value, false});
}

void glutAddSubMenu(const char* label, int subMenu) {
  Menu* menu = requireCurrentMenu("glutAddSubMenu");
  if (!menu) return;
  if (!findMenu(subMenu)) {
    warning("glutAddSubMenu: there is no menu %d", subMenu);
    return;
  }
  closePopupsShowing(menu->id);
  menu->items.push_back(MenuItem{label ? label : "", subMenu, true});
}

void glutChangeToMenuEntry(int item, const char* label, int value) {
  Menu* menu = requireCurrentMenu("glutChangeToMenuEntry");
  if (!menu) return;
  MenuItem* entry = itemOf(*menu, item, "glutChangeToMenuEntry");
  if (!entry) return;
  closePopupsShowing(menu->id);
  *entry = MenuItem{label ? label : "", value, false};
}

void glutChangeToSubMenu(int item, const char* label, int subMenu) {
  Menu* menu = requireCurrentMenu("glutChangeToSubMenu");
  if (!menu) return;
  MenuItem* entry = itemOf(*menu, item, "glutChangeToSubMenu");
  if (!entry) return;
  if (!findMenu(subMenu)) {
    warning("glutChangeToSubMenu: there is no menu %d", subMenu);
    return;
  }
  closePopupsShowing(menu->id);
  *entry = MenuItem{label ? label : "", subMenu, true};
}

void glutRemoveMenuItem(int item) {
  Menu* menu = requireCurrentMenu("glutRemoveMenuItem");
  if (!menu || !itemOf(*menu, item, "glutRemoveMenuItem")) return;
  closePopupsShowing(menu->id);
  menu->items.erase(menu->items.begin() + (item - 1));
}

void glutAttachMenu(int button) {
  Window* window = requireCurrentWindow("glutAttachMenu");
  Menu* menu = requireCurrentMenu("glutAttachMenu");
  if (!window || !menu || requireButton(button, "glutAttachMenu") < 0) return;
  window->menuOnButton[button] = menu->id;
}

void glutDetachMenu(int button) {
  Window* window = requireCurrentWindow("glutDetachMenu");
  if (!window || requireButton(button, "glutDetachMenu") < 0) return;
  window->menuOnButton[button] = 0;
}

void* glutGetMenuData(void) {
  Menu* menu = requireCurrentMenu("glutGetMenuData");
  return menu ? menu->userData : nullptr;
}

void glutSetMenuData(void* data) {
  if (Menu* menu = requireCurrentMenu("glutSetMenuData")) menu->userData = data;
}

// freeglut: the font of a menu's entries, a bitmap font (a stroke font or an unknown one is
// refused with freeglut's warning, and the menu keeps its font).
void glutSetMenuFont(int menuID, void* font) {
  requireInitialised("glutSetMenuFont");
  Menu* menu = findMenu(menuID);
  if (!menu) return;
  if (glutBitmapHeight(font) <= 0) {
    warning("glutSetMenuFont: bitmap font 0x%08lx not found. Make sure you're not passing a "
            "stroke font. Ignoring...",
            static_cast<unsigned long>(reinterpret_cast<uintptr_t>(font)));
    return;
  }
  menu->font = font;
}

// Called when the current menu is destroyed (glutDestroyMenu, or GLUT's end).
void glutMenuDestroyFunc(void (*callback)(void)) {
  if (Menu* menu = requireCurrentMenu("glutMenuDestroyFunc")) menu->destroy = callback;
}

}  // extern "C"
