/* A double-buffered animation driven by glutTimerFunc, re-armed from inside: every 40 ms the bar
 * grows by 20 pixels and the window is redrawn. The display callback first clears to red and
 * calls glFlush, which a double-buffered window does not show: no snapshot may have red in it. */
#include <GL/glut.h>

static int frame = 0;

static void tick(int value)
{
  frame = value;
  glutPostRedisplay();
  glutTimerFunc(40, tick, value + 1);
}

static void display(void)
{
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  glClearColor(0, 0, 0.5f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 0);
  glRecti(0, 40, 20 * (frame + 1), 60);
  glutSwapBuffers();
}

static void reshape(int w, int h)
{
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(200, 100);
  glutCreateWindow("timer animation");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutTimerFunc(40, tick, 1);
  glutMainLoop();
  return 0;
}
