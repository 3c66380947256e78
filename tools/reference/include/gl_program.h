/* The main() of a GL test program: render once into a width x height context and write the
 * colour buffer to the PNG named by argv[1]. The same code runs on glass and on Mesa (through
 * tools/reference/osmesa_context.c), so it uses only glass/context.h and GL.
 *
 * A GL error left after drawing fails the program (after the PNG is written, so that it can
 * still be looked at): the test programs make only valid calls, so an error means a bug. */
#ifndef GLASS_TOOLS_GL_PROGRAM_H
#define GLASS_TOOLS_GL_PROGRAM_H

#include <glass/context.h>

#include <GL/gl.h>

#include <stdio.h>

static inline int run_gl_program(int argc, char **argv, int width, int height,
                                 void (*draw)(void)) {
  GlassContext *ctx;
  int status = 0;
  if (argc != 2) {
    fprintf(stderr, "usage: %s OUTPUT.png\n", argv[0]);
    return 2;
  }
  ctx = glassCreateContext(width, height);
  if (!ctx || !glassMakeCurrent(ctx)) {
    fprintf(stderr, "%s: cannot create a %d x %d GL context\n", argv[0], width, height);
    glassDestroyContext(ctx);
    return 1;
  }

  draw();

  /* glGetError returns one recorded error per call; stop after a few in case it never clears. */
  for (int i = 0; i < 8; ++i) {
    GLenum error = glGetError();
    if (error == GL_NO_ERROR) break;
    fprintf(stderr, "%s: GL error 0x%04x\n", argv[0], (unsigned)error);
    status = 1;
  }
  if (!glassWritePNG(ctx, argv[1])) {
    fprintf(stderr, "%s: cannot write %s\n", argv[0], argv[1]);
    status = 1;
  }
  glassDestroyContext(ctx);
  return status;
}

#endif
