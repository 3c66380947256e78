/* Two windows, each with its own context and state: a green one with a white triangle, and a
 * smaller blue one with a depth-tested pair of squares. Closing the second (the window manager's
 * close button) under GLUT_ACTION_CONTINUE_EXECUTION leaves the first running; its close
 * callback says so on stdout. */
#include <stdio.h>
#include <GL/freeglut.h>

static int first, second;

static void displayFirst(void)
{
  glClearColor(0, 0.6f, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.8f, -0.8f);
  glVertex2f(0.8f, -0.8f);
  glVertex2f(0.0f, 0.8f);
  glEnd();
  glFlush();
}

static void displaySecond(void)
{
  glClearColor(0, 0, 0.6f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glRectf(-0.6f, -0.6f, 0.2f, 0.2f);
  glColor3f(1, 1, 0);
  glBegin(GL_QUADS);
  glVertex3f(-0.2f, -0.2f, 0.5f);
  glVertex3f(0.6f, -0.2f, 0.5f);
  glVertex3f(0.6f, 0.6f, 0.5f);
  glVertex3f(-0.2f, 0.6f, 0.5f);
  glEnd();
  glutSwapBuffers();
}

static void closedSecond(void)
{
  printf("window %d closed; current window %d\n", second, glutGetWindow());
  fflush(stdout);
}

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(160, 120);
  first = glutCreateWindow("first");
  glutDisplayFunc(displayFirst);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(100, 80);
  second = glutCreateWindow("second");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glClearDepth(0.0);
  glutDisplayFunc(displaySecond);
  glutCloseFunc(closedSecond);
  glutMainLoop();
  printf("glutMainLoop returned\n");
  return 0;
}
