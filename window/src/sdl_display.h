// The window system: SDL2's video subsystem. Each GLUT window is an SDL window whose surface shows
// the window's picture (Window::screen). With no display, SDL's dummy driver stands in, so that
// headless runs go through the same windows and the same loop.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "input_event.h"

namespace glass::glut {

struct Window;

// Opens the display; with allowHeadless, falls back to SDL's dummy driver when there is none.
// False when no display could be opened (then `failure` says why).
bool openDisplay(bool allowHeadless, std::string& failure);
void closeDisplay();
// True when windows are not seen by anyone (the dummy or offscreen driver).
bool displayIsHeadless();

// A borderless one for game mode (game_mode.cpp).
bool createSystemWindow(Window& window, bool borderless);
void destroySystemWindow(Window& window);
// Copies window.screen to the window's surface.
void showOnScreen(Window& window);

void setSystemWindowTitle(Window& window);
void setSystemWindowSize(Window& window, int width, int height);
void setSystemWindowPosition(Window& window, int x, int y);
// Where the window is on the screen; false when it has no system window (headless runs).
bool systemWindowPosition(const Window& window, int& x, int& y);
void setSystemWindowFullScreen(Window& window, bool fullScreen);
void showSystemWindow(Window& window, bool visible);
void iconifySystemWindow(Window& window);
void raiseSystemWindow(Window& window);
void warpSystemPointer(Window& window, int x, int y);
void setSystemCursor(Window& window, int glutCursor);
void screenSize(int& width, int& height, int& widthMM, int& heightMM);
// The screen's bits per pixel and refresh rate in Hz (0 when the system does not say).
void screenMode(int& bitsPerPixel, int& refreshRate);

// The window system's events since the last call, as GLUT input events (none when headless).
void pollSystemEvents(std::vector<InputEvent>& events);
// Sleeps until an event arrives or `milliseconds` have passed.
void waitForSystemEvent(int milliseconds);
// GLUT_ACTIVE_* now.
int systemModifiers();

}  // namespace glass::glut
