/* The buffers a window of a display mode has: argv[1] is the mode (glutInitDisplayMode's bits).
 * Prints the GL and GLUT sizes of its depth, stencil and accumulation buffers and its samples,
 * then draws a near red square and, after it, a far green one with the depth test on, and prints
 * the pixel: red with a depth buffer, green without (the test then does nothing, as on a visual
 * without depth). Then the alpha bits (GL and GLUT) and the alpha read back after clearing with
 * alpha 0.25 and after blending white by (GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA) over it: 64 and
 * a lighter grey with alpha bitplanes (GLUT_ALPHA), 255 and the grey unchanged without (the
 * destination alpha is then 1). Exits 0 after the first frame. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/glut.h>

static void square(GLfloat z)
{
  glBegin(GL_QUADS);
  glVertex3f(-1.0f, -1.0f, z);
  glVertex3f(1.0f, -1.0f, z);
  glVertex3f(1.0f, 1.0f, z);
  glVertex3f(-1.0f, 1.0f, z);
  glEnd();
}

static void display(void)
{
  GLint depth, stencil, accum, sampleBuffers, alpha;
  unsigned char pixel[4];
  glGetIntegerv(GL_DEPTH_BITS, &depth);
  glGetIntegerv(GL_STENCIL_BITS, &stencil);
  glGetIntegerv(GL_ACCUM_RED_BITS, &accum);
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
  printf("GL depth %d stencil %d accum %d sample buffers %d\n", depth, stencil, accum, sampleBuffers);
  printf("GLUT depth %d stencil %d accum %d samples %d\n", glutGet(GLUT_WINDOW_DEPTH_SIZE),
         glutGet(GLUT_WINDOW_STENCIL_SIZE), glutGet(GLUT_WINDOW_ACCUM_RED_SIZE),
         glutGet(GLUT_WINDOW_NUM_SAMPLES));
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1.0f, 0.0f, 0.0f);
  square(-0.5f);
  glColor3f(0.0f, 1.0f, 0.0f);
  square(0.5f);
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  printf("pixel %d %d %d\n", pixel[0], pixel[1], pixel[2]);
  glGetIntegerv(GL_ALPHA_BITS, &alpha);
  printf("GL alpha %d GLUT alpha %d buffer %d\n", alpha, glutGet(GLUT_WINDOW_ALPHA_SIZE),
         glutGet(GLUT_WINDOW_BUFFER_SIZE));
  glDisable(GL_DEPTH_TEST);
  glClearColor(0.5f, 0.5f, 0.5f, 0.25f);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  printf("cleared %d %d %d %d\n", pixel[0], pixel[1], pixel[2], pixel[3]);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
  glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
  square(0.0f);
  glDisable(GL_BLEND);
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  printf("blended %d %d %d %d\n", pixel[0], pixel[1], pixel[2], pixel[3]);
  fflush(stdout);
  glutSwapBuffers();
  exit(0);
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(argc > 1 ? (unsigned)atoi(argv[1]) : GLUT_RGB);
  glutInitWindowSize(64, 64);
  glutCreateWindow("display mode buffers");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
