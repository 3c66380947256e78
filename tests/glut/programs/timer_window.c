/* A square moved by glutTimerFunc, 8 pixels a tick for 12 ticks, the tick in the window's title
 * (glutSetWindowTitle) and in a text overlay; keys ask the window system for things: 'r'
 * glutReshapeWindow(400, 300), 'p' glutPositionWindow(60, 50), 'o' glutPositionWindow(0, 0),
 * 'f' glutFullScreen, 'g' prints what glutGet says of the window, 'c' posts three redisplays
 * (one display follows), 't' starts the ticks again. Every callback prints its arguments, for
 * comparison with freeglut (xvfb_differential.sh). 'q' ends it. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/freeglut.h> /* glutPositionFunc */

static int ticks = 0, width = 1, height = 1;

static void display(void)
{
  char line[64];
  const char* c;
  printf("display tick %d\n", ticks);
  fflush(stdout);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, width, 0, height);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(0.9f, 0.8f, 0.1f);
  glRecti(20 + 8 * ticks, 60, 60 + 8 * ticks, 100);
  glColor3f(0.2f, 0.7f, 0.9f);
  glBegin(GL_TRIANGLES);
  glVertex2i(width - 60, height - 20);
  glVertex2i(width - 20, height - 20);
  glVertex2i(width - 40, height - 60);
  glEnd();
  glColor3f(1, 1, 1);
  sprintf(line, "tick %d  %dx%d", ticks, width, height);
  glRasterPos2i(10, 20);
  for (c = line; *c; ++c) glutBitmapCharacter(GLUT_BITMAP_HELVETICA_12, *c);
  glutSwapBuffers();
}

static void reshape(int w, int h)
{
  printf("reshape %d %d\n", w, h);
  fflush(stdout);
  width = w;
  height = h ? h : 1;
  glViewport(0, 0, w, h);
}

static void tick(int value)
{
  char title[32];
  ticks = value;
  printf("timer %d\n", value);
  fflush(stdout);
  sprintf(title, "timer window %d", value);
  glutSetWindowTitle(title);
  if (value < 12) glutTimerFunc(30, tick, value + 1);
  glutPostRedisplay();
}

static void printGets(void)
{
  printf("glutGet window %d x %d, init %d x %d, double %d rgba %d depth %d stencil %d alpha %d, "
         "buffer %d red %d, screen %d x %d, children %d, parent %d, cursor %d\n",
         glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT), glutGet(GLUT_INIT_WINDOW_WIDTH),
         glutGet(GLUT_INIT_WINDOW_HEIGHT), glutGet(GLUT_WINDOW_DOUBLEBUFFER),
         glutGet(GLUT_WINDOW_RGBA), glutGet(GLUT_WINDOW_DEPTH_SIZE),
         glutGet(GLUT_WINDOW_STENCIL_SIZE), glutGet(GLUT_WINDOW_ALPHA_SIZE),
         glutGet(GLUT_WINDOW_BUFFER_SIZE), glutGet(GLUT_WINDOW_RED_SIZE),
         glutGet(GLUT_SCREEN_WIDTH), glutGet(GLUT_SCREEN_HEIGHT),
         glutGet(GLUT_WINDOW_NUM_CHILDREN), glutGet(GLUT_WINDOW_PARENT),
         glutGet(GLUT_WINDOW_CURSOR));
  printf("glutGet position %d %d, display mode possible %d, init mode %d\n",
         glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y), glutGet(GLUT_DISPLAY_MODE_POSSIBLE),
         glutGet(GLUT_INIT_DISPLAY_MODE));
  fflush(stdout);
}

static void keyboard(unsigned char key, int x, int y)
{
  printf("key %c at %d %d\n", key, x, y);
  fflush(stdout);
  switch (key) {
    case 'r': glutReshapeWindow(400, 300); break;
    case 'p': glutPositionWindow(60, 50); break;
    case 'o': glutPositionWindow(0, 0); break;
    case 'f': glutFullScreen(); break;
    case 'g': printGets(); break;
    case 'c': glutPostRedisplay(); glutPostRedisplay(); glutPostRedisplay(); break;
    case 't': glutTimerFunc(30, tick, 0); break;
    case 'q': exit(0);
  }
}

static void position(int x, int y)
{
  printf("position %d %d\n", x, y);
  fflush(stdout);
}

static void visibility(int state)
{
  printf("visibility %d\n", state);
  fflush(stdout);
}

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  /* Alpha, depth and stencil asked for: glass's windows always have them (RGBA8, 24-bit depth,
   * 8-bit stencil), so only with them asked does Mesa's visual have the same sizes. */
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_ALPHA | GLUT_DEPTH | GLUT_STENCIL);
  glutInitWindowSize(300, 200);
  glutInitWindowPosition(10, 10);
  glutCreateWindow("timer window");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutPositionFunc(position);
  glutVisibilityFunc(visibility);
  glClearColor(0.2f, 0.1f, 0.25f, 1);
  printGets();
  glutTimerFunc(30, tick, 1);
  glutMainLoop();
  return 0;
}
