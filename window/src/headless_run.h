// Runs without a person at the screen, for tests and scripts (docs/glut.md):
//   GLASS_GLUT_SNAPSHOT=out.png  write the window's picture to out.png once GLASS_GLUT_FRAMES
//                                frames (default 1) have been shown and the events file is done,
//                                then exit 0;
//   GLASS_GLUT_EVENTS=file       input events replayed from the file, one per line.
// The window the events go to is the last top-level one created, or the one an events file's
// `window N` names; the snapshot shows that window's top-level window, sub-windows included.
#pragma once

#include <cstdint>
#include <optional>

namespace glass::glut {

struct Window;

// Reads the variables and the events file (at glutInit); a bad file ends the program with
// file:line:col: message.
void configureHeadlessRun();
bool headlessRunRequested();

void noteFramePresented(Window& window);
// A line of the events file can run now (they start once a first frame has been shown).
bool scriptStepReady();
// When the events file's current `wait` ends, if it is waiting.
std::optional<uint64_t> scriptResumeTime();
// Runs the events file's next input line (and the `wait`, `window` or `snapshot` lines before it).
void runScriptStep();
// After a loop pass: when the frames are shown and the events file is done, writes the snapshot
// and exits.
void finishRunIfDone();
// Nothing can happen any more (no timers, no idle callback, no events left, no display): writes
// the snapshot if a frame was shown and exits, else says why there is no picture.
void finishStalledRun();

}  // namespace glass::glut
