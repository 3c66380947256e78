// What the OSMesa tests draw, and buffers to draw it into.
#pragma once

#include <GL/osmesa.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace osmesa_test {

// A lit, textured, depth-tested picture that depends on `variant` (colours, angles), drawn with
// GL and GLU calls only, ending with glFinish.
void drawScene(int variant);

// A context of the format with 24 depth and 8 stencil bits, or a failed test.
OSMesaContext createContext(GLenum format);

// Renders drawScene(variant) into a fresh RGBA / GL_UNSIGNED_BYTE buffer of width x height,
// bottom row first: the picture every other layout is checked against.
std::vector<uint8_t> renderRGBA(int width, int height, int variant);

// Renders on `threads` threads at once: thread i makes a context with makeContext(), binds it to
// an RGBA / GL_UNSIGNED_BYTE buffer of width x height, waits for the others, calls draw(i) and
// destroys the context. Returns the buffers; failures[i] is set when thread i could not make or
// bind its context, or ended with it not current or with a GL error.
std::vector<std::vector<uint8_t>> renderOnThreads(int threads, int width, int height,
                                                  const std::function<OSMesaContext()>& makeContext,
                                                  const std::function<void(int)>& draw,
                                                  std::vector<int>& failures);

}  // namespace osmesa_test
