/* GLUT misused, as freeglut reports it: argv[1] says how. */
#include <string.h>
#include <GL/glut.h>

static void display(void) { glFlush(); }

int main(int argc, char** argv)
{
  if (argc > 1 && strcmp(argv[1], "before-init") == 0) {
    glutCreateWindow("too early");
    return 0;
  }
  glutInit(&argc, argv);
  if (argc > 1 && strcmp(argv[1], "no-window") == 0) {
    glutPostRedisplay();
    return 0;
  }
  if (argc > 1 && strcmp(argv[1], "no-display-callback") == 0) {
    glutCreateWindow("no display callback");
    glutMainLoop();
    return 0;
  }
  glutCreateWindow("fine");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
