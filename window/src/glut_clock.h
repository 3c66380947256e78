// GLUT_ELAPSED_TIME: milliseconds since glutInit. With a display it is the real time. Without one
// (SDL's dummy driver, in headless runs) it is a virtual clock, so that timers and animations give
// the same frames on every run: it moves only when the event loop has nothing else to do (to the
// next timer or the end of an events file's `wait`), and by 1 ms per call of the idle callback.
#pragma once

#include <cstdint>

namespace glass::glut {

void startClock(bool isVirtual);
bool clockIsVirtual();
uint64_t elapsedMilliseconds();
// Virtual clock only: moves forward to `time` (never back).
void advanceClockTo(uint64_t time);

}  // namespace glass::glut
