// The window system's flush callback (glassSetFlushCallback in glass/context.h), run by glFlush
// and glFinish once the queued draws are in the colour buffer.
#pragma once

namespace glass::gl {

// Calls the flush callback of the context current on this thread, if it has one.
void runFlushCallback();

}  // namespace glass::gl
