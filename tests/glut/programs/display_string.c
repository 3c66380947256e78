/* glutInitDisplayString: argv[1] is the display string. Prints the display mode it gives and, once
 * the window is made, whether the window is double-buffered; exits 0 after the first frame. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/glut.h>

static void display(void)
{
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glutSwapBuffers();
  glFlush();
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  glutInitDisplayString(argc > 1 ? argv[1] : "");
  printf("mode %d\n", glutGet(GLUT_INIT_DISPLAY_MODE));
  fflush(stdout);
  glutCreateWindow("display string");
  printf("double-buffered %d\n", glutGet(GLUT_WINDOW_DOUBLEBUFFER));
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
