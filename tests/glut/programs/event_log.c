/* Prints every callback GLUT makes, with its arguments and glutGetModifiers where GLUT allows
 * it, so that a run driven by real X events (xvfb_events.sh) can be compared line by line with
 * the same program on freeglut: the order of the first reshape, visibility and display, the
 * keys, their releases and the modifiers seen in each, the wheels, and a move the program asks
 * for ('m': glutPositionWindow(30, 40)). 'q' ends it. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/freeglut.h>

static int frames = 0;

static void display(void)
{
  if (++frames <= 3) printf("display %d\n", frames);
  fflush(stdout);
  glClear(GL_COLOR_BUFFER_BIT);
  glutSwapBuffers();
}

static void reshape(int w, int h)
{
  printf("reshape %d %d\n", w, h);
  fflush(stdout);
  glViewport(0, 0, w, h);
}

static void keyboard(unsigned char key, int x, int y)
{
  printf("key %d at %d %d modifiers %d\n", key, x, y, glutGetModifiers());
  fflush(stdout);
  if (key == 'm') glutPositionWindow(30, 40);
  if (key == 'q') exit(0);
}

static void keyboardUp(unsigned char key, int x, int y)
{
  printf("key up %d at %d %d\n", key, x, y);
  fflush(stdout);
}

static void special(int key, int x, int y)
{
  printf("special %d at %d %d modifiers %d\n", key, x, y, glutGetModifiers());
  fflush(stdout);
}

static void specialUp(int key, int x, int y)
{
  printf("special up %d at %d %d\n", key, x, y);
  fflush(stdout);
}

static void mouse(int button, int state, int x, int y)
{
  printf("mouse %d %d at %d %d modifiers %d\n", button, state, x, y, glutGetModifiers());
  fflush(stdout);
}

static void motion(int x, int y)
{
  printf("motion %d %d\n", x, y);
  fflush(stdout);
}

static void passiveMotion(int x, int y)
{
  printf("passive motion %d %d\n", x, y);
  fflush(stdout);
}

static void mouseWheel(int wheel, int direction, int x, int y)
{
  printf("wheel %d %d at %d %d\n", wheel, direction, x, y);
  fflush(stdout);
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
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE);
  glutInitWindowSize(300, 200);
  glutInitWindowPosition(0, 0);
  glutCreateWindow("event log");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutKeyboardUpFunc(keyboardUp);
  glutSpecialFunc(special);
  glutSpecialUpFunc(specialUp);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  glutPassiveMotionFunc(passiveMotion);
  glutMouseWheelFunc(mouseWheel);
  glutPositionFunc(position);
  glutVisibilityFunc(visibility);
  glutMainLoop();
  return 0;
}
