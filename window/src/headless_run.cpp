#include "headless_run.h"

#include <glass/context.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "event_dispatch.h"
#include "event_script.h"
#include "glut_clock.h"
#include "glut_state.h"
#include "popup_menu.h"
#include "sdl_display.h"
#include "window_lifecycle.h"

namespace glass::glut {

namespace {

struct Run {
  std::string snapshotPath;
  int frames = 1;
  std::string eventsPath;
  std::vector<ScriptLine> script;
  size_t nextLine = 0;
  std::optional<uint64_t> resumeTime;
  int framesShown = 0;
  int targetWindow = 0;  // 0: the last window created
};

Run& run() {
  static Run instance;
  return instance;
}

[[noreturn]] void failRun(const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  std::exit(1);
}

// The window named by the last `window N` line, else the last top-level window created (its
// sub-windows get the events by where the pointer is, as a person's would).
Window* target() {
  if (Window* chosen = findWindow(run().targetWindow)) return chosen;
  auto& windows = state().windows;
  for (auto it = windows.rbegin(); it != windows.rend(); ++it) {
    if (it->second->parent == 0) return it->second.get();
  }
  return nullptr;
}

std::string where(const ScriptLine& line) {
  return run().eventsPath + ":" + std::to_string(line.line) + ":1: ";
}

// The picture of the window's top-level window, sub-windows and pop-up included: what is seen.
void writePicture(Window& window, const std::string& path) {
  const Window& top = topLevelOf(window);
  if (!glassWritePixelsPNG(path.c_str(), top.width, top.height, top.screen.data())) {
    failRun("glass: cannot write the snapshot '" + path + "'");
  }
}

bool scriptDone() { return run().nextLine >= run().script.size() && !run().resumeTime; }

void runMenuLine(Window& window, const ScriptLine& line) {
  if (window.openMenus.empty()) {
    const int menu = window.menuOnButton[2];
    if (!menu) failRun(where(line) + "no menu is open and none is attached to the right button");
    openPopup(window, menu, 2, window.mouseX, window.mouseY);
  }
  for (int entry : line.menuPath) {
    std::string error;
    Window* still = findWindow(window.id);
    if (!still || !popupChooseEntry(*still, entry, error)) failRun(where(line) + error);
  }
}

// Runs one line; true when it was an input line, after which the loop pass goes on.
bool runLine(const ScriptLine& line) {
  Run& r = run();
  Window* window = target();
  switch (line.action) {
    case ScriptAction::Wait:
      if (line.number > 0) r.resumeTime = elapsedMilliseconds() + static_cast<uint64_t>(line.number);
      return true;
    case ScriptAction::SelectWindow:
      if (!findWindow(line.number)) failRun(where(line) + "there is no window " + std::to_string(line.number));
      r.targetWindow = line.number;
      return false;
    case ScriptAction::Snapshot:
      if (!window) failRun(where(line) + "there is no window to take a snapshot of");
      writePicture(*window, line.path);
      return false;
    default: break;
  }
  if (!window) failRun(where(line) + "there is no window for the event");
  switch (line.action) {
    case ScriptAction::Input:
      for (InputEvent event : line.events) {
        event.window = window->id;
        if (event.kind == InputKind::Key || event.kind == InputKind::KeyUp ||
            event.kind == InputKind::Special || event.kind == InputKind::SpecialUp) {
          event.x = window->mouseX;  // keys are pressed where the pointer is
          event.y = window->mouseY;
        }
        dispatchInput(event);
      }
      break;
    case ScriptAction::Menu: runMenuLine(*window, line); break;
    case ScriptAction::Reshape: {
      InputEvent event;
      event.kind = InputKind::Reshape;
      event.window = window->id;
      event.width = line.width;
      event.height = line.height;
      dispatchInput(event);
      break;
    }
    case ScriptAction::Close: closeWindowFromSystem(*window); break;
    default: break;
  }
  return true;
}

}  // namespace

void configureHeadlessRun() {
  Run& r = run();
  r = Run{};
  if (const char* snapshot = std::getenv("GLASS_GLUT_SNAPSHOT"); snapshot && *snapshot) {
    r.snapshotPath = snapshot;
  }
  if (const char* frames = std::getenv("GLASS_GLUT_FRAMES"); frames && *frames) {
    char* end = nullptr;
    const long count = std::strtol(frames, &end, 10);
    if (*end != '\0' || count < 1 || count > 1000000) {
      failRun(std::string("glass: GLASS_GLUT_FRAMES must be a whole number from 1, not '") + frames + "'");
    }
    r.frames = static_cast<int>(count);
  }
  if (const char* events = std::getenv("GLASS_GLUT_EVENTS"); events && *events) {
    r.eventsPath = events;
    std::string error;
    if (!readEventScript(r.eventsPath, r.script, error)) failRun(error);
  }
}

bool headlessRunRequested() { return !run().snapshotPath.empty() || !run().eventsPath.empty(); }

void noteFramePresented(Window&) { ++run().framesShown; }

// The events start once the first frame is shown, as a person starts once the window shows.
bool scriptStepReady() {
  const Run& r = run();
  if (r.resumeTime && elapsedMilliseconds() < *r.resumeTime) return false;
  return r.framesShown > 0 && r.nextLine < r.script.size() && !state().windows.empty();
}

std::optional<uint64_t> scriptResumeTime() { return run().resumeTime; }

void runScriptStep() {
  Run& r = run();
  if (r.resumeTime && elapsedMilliseconds() >= *r.resumeTime) r.resumeTime.reset();
  if (!scriptStepReady()) return;
  while (r.nextLine < r.script.size()) {
    const ScriptLine& line = r.script[r.nextLine++];
    if (runLine(line)) return;
  }
}

void finishRunIfDone() {
  const Run& r = run();
  if (!headlessRunRequested() || !scriptDone()) return;
  if (r.snapshotPath.empty()) {
    // Only an events file: without a display the run is over; with one, the person at the
    // screen goes on.
    if (displayIsHeadless()) {
      deinitialise();
      std::exit(0);
    }
    return;
  }
  if (r.framesShown < r.frames) return;
  Window* window = target();
  if (!window) failRun("glass: there is no window to take the snapshot of");
  writePicture(*window, r.snapshotPath);
  deinitialise();
  std::exit(0);
}

void finishStalledRun() {
  const Run& r = run();
  if (r.snapshotPath.empty()) {
    std::fprintf(stderr, "glass: no display, no GLASS_GLUT_SNAPSHOT, and nothing left to happen: "
                         "the program ends\n");
    deinitialise();
    std::exit(0);
  }
  Window* window = target();
  if (r.framesShown == 0 || !window) {
    failRun("glass: the program showed no picture, and nothing left can make it (a single-buffered "
            "window shows its picture on glFlush or glFinish, a double-buffered one on "
            "glutSwapBuffers)");
  }
  std::fprintf(stderr,
               "glass: GLASS_GLUT_FRAMES is %d, but the program showed %d frame%s and then waited "
               "for input; the snapshot shows the last\n",
               r.frames, r.framesShown, r.framesShown == 1 ? "" : "s");
  writePicture(*window, r.snapshotPath);
  deinitialise();
  std::exit(0);
}

}  // namespace glass::glut
