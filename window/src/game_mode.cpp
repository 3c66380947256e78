// Game mode (GLUT 3.7's glutGameModeString, glutEnterGameMode, glutLeaveGameMode,
// glutGameModeGet). A GLUT game mode takes the whole screen at the asked resolution; glass does
// not change the screen's video mode: the game mode window is a borderless window of the asked
// size at the screen's corner (the screen's own size when none is asked, which covers it), with
// a context of that size. As freeglut, entering game mode again replaces the window, and the
// mode counts as changed while the window exists.
#include <GL/freeglut.h>

#include <cstdio>
#include <string>

#include "glut_errors.h"
#include "glut_state.h"
#include "sdl_display.h"
#include "window_lifecycle.h"

namespace glass::glut {
namespace {

// The largest side glass makes a window's context (GL_MAX_VIEWPORT_DIMS).
constexpr int kMaxGameModeSide = 16384;

struct GameMode {
  int width, height, depth, refresh;
};

// What the game mode string asked, the screen's own values for what it did not.
GameMode chosenGameMode() {
  const State& s = state();
  int screenWidth = 0, screenHeight = 0, widthMM = 0, heightMM = 0, depth = 0, refresh = 0;
  screenSize(screenWidth, screenHeight, widthMM, heightMM);
  screenMode(depth, refresh);
  return {s.gameModeWidth > 0 ? s.gameModeWidth : screenWidth,
          s.gameModeHeight > 0 ? s.gameModeHeight : screenHeight,
          s.gameModeDepth > 0 ? s.gameModeDepth : depth,
          s.gameModeRefresh > 0 ? s.gameModeRefresh : refresh};
}

bool possible(const GameMode& mode) {
  return mode.width > 0 && mode.height > 0 && mode.width <= kMaxGameModeSide &&
         mode.height <= kMaxGameModeSide;
}

}  // namespace
}  // namespace glass::glut

using namespace glass::glut;

extern "C" {

// "[WIDTHxHEIGHT][:BITS][@HZ]", each part optional (spec 11.1): "640x480:16@60", "800x600",
// ":32", "@75". A part that does not read leaves that setting as it was.
void glutGameModeString(const char* string) {
  requireInitialised("glutGameModeString");
  if (!string) return;
  State& s = state();
  const std::string text = string;
  int width = 0, height = 0, depth = 0, refresh = 0;
  const std::size_t colon = text.find(':'), at = text.find('@');
  if (std::sscanf(text.c_str(), "%dx%d", &width, &height) == 2 && width > 0 && height > 0) {
    s.gameModeWidth = width;
    s.gameModeHeight = height;
  }
  if (colon != std::string::npos && std::sscanf(text.c_str() + colon + 1, "%d", &depth) == 1 && depth > 0) {
    s.gameModeDepth = depth;
  }
  if (at != std::string::npos && std::sscanf(text.c_str() + at + 1, "%d", &refresh) == 1 && refresh > 0) {
    s.gameModeRefresh = refresh;
  }
}

int glutEnterGameMode(void) {
  requireInitialised("glutEnterGameMode");
  State& s = state();
  const GameMode mode = chosenGameMode();
  if (!possible(mode)) {
    warning("failed to change the screen to %d x %d for game mode", mode.width, mode.height);
    return 0;
  }
  if (s.gameModeWindow != 0) destroyWindow(s.gameModeWindow);
  s.gameModeWindow = createTopLevelWindow("FREEGLUT", 0, 0, mode.width, mode.height, true);
  return s.gameModeWindow;
}

void glutLeaveGameMode(void) {
  requireInitialised("glutLeaveGameMode");
  if (state().gameModeWindow != 0) destroyWindow(state().gameModeWindow);
}

int glutGameModeGet(GLenum query) {
  requireInitialised("glutGameModeGet");
  const State& s = state();
  const GameMode mode = chosenGameMode();
  switch (query) {
    case GLUT_GAME_MODE_ACTIVE:
    case GLUT_GAME_MODE_DISPLAY_CHANGED: return s.gameModeWindow != 0 ? 1 : 0;
    case GLUT_GAME_MODE_POSSIBLE: return possible(mode) ? 1 : 0;
    case GLUT_GAME_MODE_WIDTH: return mode.width;
    case GLUT_GAME_MODE_HEIGHT: return mode.height;
    case GLUT_GAME_MODE_PIXEL_DEPTH: return mode.depth;
    case GLUT_GAME_MODE_REFRESH_RATE: return mode.refresh;
    default:
      warning("Unknown gamemode get: %d", static_cast<int>(query));
      return -1;
  }
}

}  // extern "C"
