/* An installed-glass user: built by the install test with
 *   cc program.c $(pkg-config --cflags --libs glass)
 * and by a CMake project through find_package(glass) and glass::gl. It must see glass's GL
 * header, not the system's, and render: a red triangle over a blue background, checked through
 * glReadPixels. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <glass/context.h>

#include <stdio.h>

#ifndef GLASS_GL
#error "<GL/gl.h> is not glass's header: GLASS_GL is not defined"
#endif

static int pixelIs(int x, int y, unsigned char r, unsigned char g, unsigned char b)
{
  unsigned char rgba[4] = {0, 0, 0, 0};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  if (rgba[0] == r && rgba[1] == g && rgba[2] == b) return 1;
  fprintf(stderr, "pixel (%d, %d) is %d %d %d, expected %d %d %d\n", x, y, rgba[0], rgba[1],
          rgba[2], r, g, b);
  return 0;
}

int main(void)
{
  GlassContext *ctx = glassCreateContext(64, 64);
  int ok;
  if (!ctx || !glassMakeCurrent(ctx)) {
    fprintf(stderr, "cannot create a glass context\n");
    return 1;
  }
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, 64.0, 0.0, 64.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  glBegin(GL_TRIANGLES);
  glVertex2f(8.0f, 8.0f);
  glVertex2f(56.0f, 8.0f);
  glVertex2f(32.0f, 56.0f);
  glEnd();
  glFinish();

  ok = pixelIs(32, 20, 255, 0, 0) && pixelIs(2, 60, 0, 0, 255) && glGetError() == GL_NO_ERROR;
  glassDestroyContext(ctx);
  if (ok) printf("installed glass renders\n");
  return ok ? 0 : 1;
}
