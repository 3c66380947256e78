/* A right-button menu with a submenu, as homework 4 asks: the menu's callback changes the
 * picture. Entries: "Red background" (1), "Blue background" (2), "Shape" -> "Square" (10),
 * "Triangle" (11), and "Quit" (99). */
#include <stdlib.h>
#include <GL/glut.h>

static float background[3] = {0.0f, 0.0f, 0.0f};
static int shape = 10;

static void choose(int value)
{
  switch (value) {
  case 1: background[0] = 1; background[1] = 0; background[2] = 0; break;
  case 2: background[0] = 0; background[1] = 0; background[2] = 1; break;
  case 10:
  case 11: shape = value; break;
  case 99: exit(0);
  }
  glutPostRedisplay();
}

static void display(void)
{
  glClearColor(background[0], background[1], background[2], 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  if (shape == 10) {
    glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  } else {
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.0f, 0.5f);
    glEnd();
  }
  glFlush();
}

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("menu");
  glutDisplayFunc(display);
  int shapes = glutCreateMenu(choose);
  glutAddMenuEntry("Square", 10);
  glutAddMenuEntry("Triangle", 11);
  glutCreateMenu(choose);
  glutAddMenuEntry("Red background", 1);
  glutAddMenuEntry("Blue background", 2);
  glutAddSubMenu("Shape", shapes);
  glutAddMenuEntry("Quit", 99);
  glutAttachMenu(GLUT_RIGHT_BUTTON);
  glutMainLoop();
  return 0;
}
