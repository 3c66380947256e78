/* A double-buffered window's two colour buffers, as a program drawing rubber bands in the front
 * buffer uses them. Prints GL_DOUBLEBUFFER and the initial draw and read buffers; the first
 * frame clears the back buffer to blue, draws a red square on its left half and swaps. Key f
 * draws an XOR green square over the middle into the front buffer and flushes (shown at once);
 * key b selects GL_FRONT_AND_BACK and draws a white square, half transparent, at the bottom
 * right (blended into each buffer's own pixels); key p pushes the colour-buffer attributes,
 * selects the front buffer and pops them; key r prints the pixels of both buffers at the middle
 * (50, 50), the left half (25, 50) and the bottom right (80, 20) with glReadBuffer; key s swaps
 * without drawing; key q exits. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/glut.h>

static void square(GLfloat x0, GLfloat y0, GLfloat x1, GLfloat y1)
{
  glBegin(GL_QUADS);
  glVertex2f(x0, y0);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glVertex2f(x0, y1);
  glEnd();
}

static const char *bufferName(GLint buffer)
{
  switch (buffer) {
  case GL_FRONT: return "GL_FRONT";
  case GL_BACK: return "GL_BACK";
  case GL_FRONT_AND_BACK: return "GL_FRONT_AND_BACK";
  default: return "other";
  }
}

static void printBuffers(const char *when)
{
  GLboolean doubleBuffer = GL_FALSE;
  GLint draw = 0, read = 0;
  glGetBooleanv(GL_DOUBLEBUFFER, &doubleBuffer);
  glGetIntegerv(GL_DRAW_BUFFER, &draw);
  glGetIntegerv(GL_READ_BUFFER, &read);
  printf("%s: double buffer %d, draw %s, read %s\n", when, doubleBuffer, bufferName(draw), bufferName(read));
}

static void printPixels(void)
{
  static const int at[3][2] = {{50, 50}, {25, 50}, {80, 20}};
  static const GLenum buffers[2] = {GL_FRONT, GL_BACK};
  GLint read = 0;
  glGetIntegerv(GL_READ_BUFFER, &read);
  for (int b = 0; b < 2; ++b) {
    glReadBuffer(buffers[b]);
    printf("%s:", b == 0 ? "front" : "back");
    for (int i = 0; i < 3; ++i) {
      unsigned char pixel[4];
      glReadPixels(at[i][0], at[i][1], 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
      printf(" (%d %d %d)", pixel[0], pixel[1], pixel[2]);
    }
    printf("\n");
  }
  glReadBuffer((GLenum)read);
  fflush(stdout);
}

static void display(void)
{
  glClearColor(0.0f, 0.0f, 0.4f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  square(-1.0f, -1.0f, 0.0f, 1.0f);
  glutSwapBuffers();
  printf("frame\n");
  fflush(stdout);
}

static void key(unsigned char k, int x, int y)
{
  (void)x;
  (void)y;
  switch (k) {
  case 'f':
    glDrawBuffer(GL_FRONT);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glColor3f(0.0f, 1.0f, 0.0f);
    square(-0.4f, -0.4f, 0.4f, 0.4f);
    glDisable(GL_COLOR_LOGIC_OP);
    glFlush();
    glDrawBuffer(GL_BACK);
    break;
  case 'b':
    glDrawBuffer(GL_FRONT_AND_BACK);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
    square(0.4f, -1.0f, 1.0f, -0.4f);
    glDisable(GL_BLEND);
    glFlush();
    printBuffers("both");
    glDrawBuffer(GL_BACK);
    break;
  case 'p':
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glDrawBuffer(GL_FRONT);
    printBuffers("pushed");
    glPopAttrib();
    printBuffers("popped");
    break;
  case 'r': printPixels(); break;
  case 's': glutSwapBuffers(); printf("swapped\n"); fflush(stdout); break;
  case 'q': exit(0);
  default: break;
  }
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(100, 100);
  glutInitWindowPosition(0, 0);
  glutCreateWindow("front buffer");
  printBuffers("created");
  glutDisplayFunc(display);
  glutKeyboardFunc(key);
  glutMainLoop();
  return 0;
}
