/* A teapot turned by dragging with the left button (Shift+drag moves it nearer and farther), the
 * arrow keys (15 degrees), Page Up and Page Down (distance), F1 (back to the start) and Home (the
 * text overlay on and off); the reshape callback keeps the aspect ratio with gluPerspective, and
 * a line of glutBitmapCharacter text shows the state. Every callback prints its arguments and
 * glutGetModifiers, for comparison with freeglut (xvfb_differential.sh). 'q' ends it. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/glut.h>

static int width = 1, height = 1;
static int rotX = 20, rotY = -30, distance = 60; /* distance in tenths */
static int dragging = 0, zooming = 0, lastX = 0, lastY = 0, showText = 1;

static void text(int x, int y, const char* s)
{
  glRasterPos2i(x, y);
  while (*s) glutBitmapCharacter(GLUT_BITMAP_8_BY_13, *s++);
}

static void display(void)
{
  static const GLfloat gold[4] = {0.8f, 0.6f, 0.2f, 1};
  char line[80];
  printf("display rot %d %d distance %d\n", rotX, rotY, distance);
  fflush(stdout);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -distance / 10.0f);
  glRotatef((GLfloat)rotX, 1, 0, 0);
  glRotatef((GLfloat)rotY, 0, 1, 0);
  glEnable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, gold);
  glFrontFace(GL_CW);
  glutSolidTeapot(1.0);
  glFrontFace(GL_CCW);
  if (showText) {
    /* The overlay in window coordinates, as the textbooks do it. */
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    gluOrtho2D(0, width, 0, height);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1, 1, 1);
    sprintf(line, "rot %d %d  dist %d", rotX, rotY, distance);
    text(8, 8, line);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
  }
  glutSwapBuffers();
}

static void reshape(int w, int h)
{
  printf("reshape %d %d, glutGet %d %d\n", w, h, glutGet(GLUT_WINDOW_WIDTH),
         glutGet(GLUT_WINDOW_HEIGHT));
  fflush(stdout);
  width = w;
  height = h ? h : 1;
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(35.0, (double)width / height, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
}

static void mouse(int button, int state, int x, int y)
{
  int modifiers = glutGetModifiers();
  printf("mouse %d %d at %d %d modifiers %d\n", button, state, x, y, modifiers);
  fflush(stdout);
  if (button == GLUT_LEFT_BUTTON) {
    dragging = state == GLUT_DOWN;
    zooming = dragging && (modifiers & GLUT_ACTIVE_SHIFT);
    lastX = x;
    lastY = y;
  }
}

static void motion(int x, int y)
{
  printf("motion %d %d\n", x, y);
  fflush(stdout);
  if (!dragging) return;
  if (zooming) {
    distance += y - lastY;
    if (distance < 30) distance = 30;
  } else {
    rotY += x - lastX;
    rotX += y - lastY;
  }
  lastX = x;
  lastY = y;
  glutPostRedisplay();
}

static void special(int key, int x, int y)
{
  printf("special %d at %d %d modifiers %d\n", key, x, y, glutGetModifiers());
  fflush(stdout);
  switch (key) {
    case GLUT_KEY_LEFT: rotY -= 15; break;
    case GLUT_KEY_RIGHT: rotY += 15; break;
    case GLUT_KEY_UP: rotX -= 15; break;
    case GLUT_KEY_DOWN: rotX += 15; break;
    case GLUT_KEY_PAGE_UP: distance -= 5; break;
    case GLUT_KEY_PAGE_DOWN: distance += 5; break;
    case GLUT_KEY_F1: rotX = 20; rotY = -30; distance = 60; break;
    case GLUT_KEY_HOME: showText = !showText; break;
    default: return;
  }
  glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y)
{
  printf("key %d at %d %d modifiers %d\n", key, x, y, glutGetModifiers());
  fflush(stdout);
  if (key == 'q') exit(0);
}

int main(int argc, char** argv)
{
  static const GLfloat lightPosition[4] = {-3, 4, 5, 0};
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(360, 270);
  glutInitWindowPosition(20, 30);
  glutCreateWindow("drag teapot");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  glutSpecialFunc(special);
  glutKeyboardFunc(keyboard);
  glClearColor(0.15f, 0.2f, 0.25f, 1);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glutMainLoop();
  return 0;
}
