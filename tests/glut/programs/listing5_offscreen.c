/* Listing 5's calls without GLUT: the same functions (linked from listing5.c, whose main is
 * renamed) on an off-screen glass context of the window's size, in the order GLUT makes them:
 * initRendering after the window is made, the reshape callback with the size, then the display
 * callback once per step, as the space bar steps on. Writes argv[2] at step argv[1]. */
#include <stdio.h>
#include <stdlib.h>

#include <GL/gl.h>
#include <glass/context.h>

extern int CurrentStep;
void drawScene(void);
void initRendering(void);
void resizeWindow(int w, int h);

int main(int argc, char** argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: listing5_offscreen STEP OUT.png\n");
    return 2;
  }
  GlassContext* context = glassCreateContext(500, 500);
  glassMakeCurrent(context);
  initRendering();
  resizeWindow(500, 500);
  const int lastStep = atoi(argv[1]);
  for (CurrentStep = 0; CurrentStep <= lastStep; ++CurrentStep) drawScene();
  const int written = glassWritePNG(context, argv[2]);
  glassDestroyContext(context);
  return written ? 0 : 1;
}
