#include "view_key.h"

#include <GL/freeglut.h>
#include <glass/context.h>

#include <cstdio>
#include <iterator>

#include "glut_state.h"
#include "sdl_display.h"

namespace glass::glut {
namespace {

// The views in the order the key steps through them; "off" (nullptr) before the first.
constexpr const char* kViews[] = {nullptr, "depth", "overdraw", "wireframe", "normals", "mipmap"};
constexpr int kViewCount = static_cast<int>(std::size(kViews));

// The character Ctrl+V gives (0x16, as X's XLookupString and the events file give it).
constexpr int kControlV = 'v' & 0x1f;

int positionOf(const char* view) {
  for (int i = 1; i < kViewCount; ++i) {
    if (view && std::string(view) == kViews[i]) return i;
  }
  return 0;
}

}  // namespace

bool takeViewKey(Window& window, const InputEvent& event) {
  if (event.kind != InputKind::Key && event.kind != InputKind::KeyUp) return false;
  constexpr int both = GLUT_ACTIVE_CTRL | GLUT_ACTIVE_ALT;
  if (event.key != kControlV || (event.modifiers & both) != both) return false;
  if (event.kind == InputKind::KeyUp) return true;
  const int step = (event.modifiers & GLUT_ACTIVE_SHIFT) ? kViewCount - 1 : 1;
  const char* next = kViews[(positionOf(glassGetView(window.context)) + step) % kViewCount];
  if (!glassSetView(window.context, next)) return true;
  std::fprintf(stderr, "glass: Ctrl+Alt+V: %s%s\n", next ? "view " : "the program's picture",
               next ? next : "");
  setSystemWindowTitle(window);
  // The view's picture is made as the program draws: the program draws its frame again.
  window.redisplayPending = true;
  return true;
}

std::string shownTitle(const Window& window) {
  const char* view = glassGetView(window.context);
  return view ? window.title + " [glass: " + view + "]" : window.title;
}

}  // namespace glass::glut
