#include "glut_clock.h"

#include <SDL.h>

namespace glass::glut {

namespace {
bool virtualClock = false;
uint64_t startTicks = 0;
uint64_t virtualNow = 0;
}  // namespace

void startClock(bool isVirtual) {
  virtualClock = isVirtual;
  virtualNow = 0;
  startTicks = SDL_GetTicks64();
}

bool clockIsVirtual() { return virtualClock; }

uint64_t elapsedMilliseconds() {
  return virtualClock ? virtualNow : SDL_GetTicks64() - startTicks;
}

void advanceClockTo(uint64_t time) {
  if (virtualClock && time > virtualNow) virtualNow = time;
}

}  // namespace glass::glut
