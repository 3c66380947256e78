// The event loop (GLUT 3.7 spec 3, freeglut's glutMainLoopEvent and glutLeaveMainLoop): each pass
// takes the window system's events (and the next lines of an events file), runs the timers that
// are due, then the pending reshape and display callbacks; between passes the idle callback runs,
// or the loop sleeps until the next event or timer.
#include <GL/freeglut.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "event_dispatch.h"
#include "glut_clock.h"
#include "glut_errors.h"
#include "glut_state.h"
#include "headless_run.h"
#include "presentation.h"
#include "sdl_display.h"
#include "window_lifecycle.h"

namespace glass::glut {

namespace {

void runDueTimers() {
  State& s = state();
  const uint64_t now = elapsedMilliseconds();
  // A timer callback may set new timers (often itself, re-armed): those wait for a later pass,
  // even when due at once, so that a zero-delay timer cannot starve the loop.
  std::vector<Timer> due;
  auto notDue = std::stable_partition(s.timers.begin(), s.timers.end(),
                                      [now](const Timer& t) { return t.deadline > now; });
  due.assign(notDue, s.timers.end());
  s.timers.erase(notDue, s.timers.end());
  std::sort(due.begin(), due.end(), [](const Timer& a, const Timer& b) {
    return a.deadline != b.deadline ? a.deadline < b.deadline : a.order < b.order;
  });
  for (const Timer& timer : due) timer.callback(timer.value);
}

// Runs `work` for each window that still exists, in the order of their ids; a callback may
// destroy windows, including the one it runs for.
template <class Work>
void forEachWindow(Work&& work) {
  std::vector<int> ids;
  for (const auto& [id, window] : state().windows) ids.push_back(id);
  for (int id : ids) {
    if (Window* window = findWindow(id)) work(*window);
  }
}

// The move the program asked for (glutPositionWindow), told as the window system's moves are.
void runMove(Window& window) {
  if (!window.movePending) return;
  window.movePending = false;
  InputEvent moved;
  moved.kind = InputKind::Moved;
  moved.window = window.id;
  moved.x = window.requestedX;
  moved.y = window.requestedY;
  systemWindowPosition(window, moved.x, moved.y);
  dispatchInput(moved);
}

void runReshape(Window& window) {
  if (window.requestedWidth > 0) {
    const bool changes =
        window.width != window.requestedWidth || window.height != window.requestedHeight;
    resizeWindow(window, window.requestedWidth, window.requestedHeight);
    window.requestedWidth = window.requestedHeight = 0;
    // freeglut reshapes and draws a window on X's ConfigureNotify, which comes with the expose
    // of the new size, and draws it once for both. glass reshapes it at once, so the expose that
    // follows is of a picture already drawn at that size: it only shows it again (event_dispatch).
    window.resizeExposeAwaited =
        changes && window.sdlWindow && !window.parent && !displayIsHeadless();
  }
  if (!window.reshapePending) return;
  window.reshapePending = false;
  makeCurrent(window);
  if (window.callbacks.reshape) {
    window.callbacks.reshape(window.width, window.height);
  } else {
    glViewport(0, 0, window.width, window.height);  // GLUT's default reshape (spec 7.2)
  }
}

// A new window's position (when it is not at (0, 0)) and first reshape come first in the pass.
void runReshapes() {
  forEachWindow([](Window& window) {
    if (!window.firstPassDone) runMove(window);
    if (Window* still = findWindow(window.id)) runReshape(*still);
  });
}

// Each window's move, then its reshape. A sub-window comes after its parent (its id is larger),
// so what the parent's reshape callback asks of it (the layout of the classic programs' panes)
// is done in the same pass, before the displays.
void runMovesAndReshapes() {
  forEachWindow([](Window& window) {
    runMove(window);
    if (Window* still = findWindow(window.id)) runReshape(*still);
  });
}

void runDisplays() {
  forEachWindow([](Window& window) {
    if (!window.firstPassDone) {
      window.firstPassDone = true;
      if (!window.callbacks.display) {
        fatalError("ERROR:  No display callback registered for window %d\n", window.id);
      }
    }
    if (!window.redisplayPending || !window.visible) return;
    window.redisplayPending = false;
    makeCurrent(window);
    window.inDisplayCallback = true;
    window.presentedInDisplay = false;
    window.callbacks.display();
    if (Window* still = findWindow(window.id)) {
      still->inDisplayCallback = false;
      if (still->presentedInDisplay) noteFramePresented(*still);
    }
  });
}

bool anyRedisplayPending() {
  for (const auto& [id, window] : state().windows) {
    if ((window->redisplayPending && window->visible) || window->reshapePending ||
        window->requestedWidth > 0 || window->movePending) {
      return true;
    }
  }
  return false;
}

// When the next timer or scripted step is due; max when none is.
uint64_t nextWakeTime() {
  uint64_t next = std::numeric_limits<uint64_t>::max();
  for (const Timer& timer : state().timers) next = std::min(next, timer.deadline);
  if (const auto resume = scriptResumeTime()) next = std::min(next, *resume);
  return next;
}

// Between passes, with no idle callback: sleep until something is to do.
void waitForWork() {
  if (anyRedisplayPending() || scriptStepReady()) return;
  const uint64_t next = nextWakeTime();
  if (clockIsVirtual()) {
    if (next == std::numeric_limits<uint64_t>::max()) {
      finishStalledRun();  // nothing can ever happen again
      return;
    }
    advanceClockTo(next);
    return;
  }
  const uint64_t now = elapsedMilliseconds();
  const uint64_t wait = next > now ? std::min<uint64_t>(next - now, 100) : 0;
  waitForSystemEvent(static_cast<int>(wait));
}

// With GLUT_SKIP_STALE_MOTION_EVENTS set, whether events[i] is a motion that the next event, a
// motion of the same window, makes stale (freeglut on X skips to the last motion queued).
bool isStaleMotion(const std::vector<InputEvent>& events, size_t i) {
  if (!state().skipStaleMotion || i + 1 >= events.size()) return false;
  const InputEvent &e = events[i], &next = events[i + 1];
  return e.kind == InputKind::Motion && next.kind == InputKind::Motion && next.window == e.window;
}

}  // namespace

void runLoopPass() {
  // A new window's first reshape comes before the events of its showing (visibility, entry), as
  // freeglut delivers them.
  runReshapes();
  std::vector<InputEvent> events;
  pollSystemEvents(events);
  for (size_t i = 0; i < events.size(); ++i) {
    if (isStaleMotion(events, i)) continue;
    dispatchInput(events[i]);
  }
  runScriptStep();
  runDueTimers();
  runMovesAndReshapes();
  runDisplays();
  finishRunIfDone();
}

}  // namespace glass::glut

using namespace glass::glut;

extern "C" {

void glutMainLoopEvent(void) {
  requireInitialised("glutMainLoopEvent");
  runLoopPass();
}

void glutMainLoop(void) {
  requireInitialised("glutMainLoop");
  State& s = state();
  if (s.windows.empty()) fatalError(" ERROR:  glutMainLoop called with no windows created.");
  s.loopRunning = true;
  while (s.loopRunning) {
    runLoopPass();
    if (!s.loopRunning) break;
    if (s.windows.empty()) {
      s.loopRunning = false;
      break;
    }
    if (s.idle) {
      // Keep a current window for the idle callback, as freeglut does.
      if (!currentWindow()) makeCurrent(*s.windows.begin()->second);
      s.idle();
      if (clockIsVirtual()) advanceClockTo(elapsedMilliseconds() + 1);
    } else {
      waitForWork();
    }
  }
  // As freeglut: the loop ends by glutLeaveMainLoop or by closing windows; GLUT is then
  // deinitialised, and under GLUT_ACTION_EXIT the program ends.
  const int action = s.actionOnWindowClose;
  deinitialise();
  if (action == GLUT_ACTION_EXIT) std::exit(0);
}

void glutLeaveMainLoop(void) {
  requireInitialised("glutLeaveMainLoop");
  state().loopRunning = false;
}

void glutIdleFunc(void (*callback)(void)) {
  requireInitialised("glutIdleFunc");
  state().idle = callback;
}

void glutTimerFunc(unsigned int time, void (*callback)(int), int value) {
  requireInitialised("glutTimerFunc");
  if (!callback) return;
  State& s = state();
  s.timers.push_back(Timer{elapsedMilliseconds() + time, s.nextTimerOrder++, callback, value});
}

}  // extern "C"
