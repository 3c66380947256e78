// The pop-up menus: opened by the button they are attached to, drawn by glass over the window's
// picture (with freeglut's layout, colours and font: Helvetica 18), picked with the pointer;
// a submenu opens beside its entry when the pointer rests on it.
#pragma once

#include <string>

namespace glass::glut {

struct Window;

void openPopup(Window& window, int menu, int button, int x, int y);
void closePopup(Window& window);
// A button press or release while the pop-up is open; true when the pop-up took it.
bool popupTakesButton(Window& window, int button, int buttonState, int x, int y);
void popupFollowPointer(Window& window, int x, int y);
// Chooses entry `index` (0-based) of the deepest open menu, as a click on it would: a submenu
// opens, an entry closes the pop-up and calls the menu's callback. False, with `error`, when
// there is no such entry.
bool popupChooseEntry(Window& window, int index, std::string& error);
// Draws the open menus over window.screen (the picture with its sub-windows).
void drawPopupOverPicture(Window& window);

}  // namespace glass::glut
