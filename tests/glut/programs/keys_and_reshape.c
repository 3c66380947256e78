/* Keyboard, special keys, modifiers and reshape: the arrow keys move a 20 x 20 square on a grid
 * of 20-pixel cells, 'r' and 'R' make it red, 'g' green (with Ctrl, Ctrl+G is character 7 and
 * makes it blue), and a reshape keeps one pixel per unit with the origin at the bottom left.
 * Every key the keyboard callbacks get is printed, with its modifiers; 'p' also prints where the
 * window is (glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y)) and its cursor. */
#include <stdio.h>
#include <GL/glut.h>

static int column = 0, row = 0;
static float color[3] = {1, 1, 1};

static void keyboard(unsigned char key, int x, int y)
{
  (void)x; (void)y;
  printf("key %d modifiers %d\n", key, glutGetModifiers());
  fflush(stdout);
  if (key == 'r' || key == 'R') { color[0] = 1; color[1] = 0; color[2] = 0; }
  if (key == 'g') { color[0] = 0; color[1] = 1; color[2] = 0; }
  if (key == 'p') {
    printf("position %d %d\n", glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y));
    printf("cursor %d\n", glutGet(GLUT_WINDOW_CURSOR));
  }
  if (key == 7 && (glutGetModifiers() & GLUT_ACTIVE_CTRL)) { color[0] = 0; color[1] = 0; color[2] = 1; }
  glutPostRedisplay();
}

static void keyboardUp(unsigned char key, int x, int y)
{
  (void)x; (void)y;
  printf("key up %d\n", key);
  fflush(stdout);
}

static void special(int key, int x, int y)
{
  (void)x; (void)y;
  switch (key) {
  case GLUT_KEY_LEFT: --column; break;
  case GLUT_KEY_RIGHT: ++column; break;
  case GLUT_KEY_UP: ++row; break;
  case GLUT_KEY_DOWN: --row; break;
  }
  glutPostRedisplay();
}

static void reshape(int w, int h)
{
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  printf("reshape %d %d\n", glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT));
  fflush(stdout);
}

static void display(void)
{
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3fv(color);
  glRecti(20 * column, 20 * row, 20 * column + 20, 20 * row + 20);
  glFlush();
}

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  glutInitWindowSize(200, 200);
  glutCreateWindow("keys");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutKeyboardUpFunc(keyboardUp);
  glutSpecialFunc(special);
  glutMainLoop();
  return 0;
}
