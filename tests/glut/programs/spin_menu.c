/* A textbook spinning cube: double-buffered, lit, turned by the idle callback, with a right-button
 * menu of submenus (colour, shape) and an entry that changes its own label
 * (glutChangeToMenuEntry). Every callback prints its arguments, so that a run driven by real X
 * events (xvfb_differential.sh) can be compared line by line with the same program on freeglut.
 * The spin is deterministic: 's' (or the menu) asks for 90 more degrees, and the idle callback
 * turns the cube 10 degrees a call until it gets there, then removes itself. 'q' ends it. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/glut.h>

static int angle = 0, target = 0;
static int colour = 10, shape = 20, wire = 0;
static int mainMenu;

static void display(void)
{
  static const GLfloat colours[3][4] = {
      {0.9f, 0.2f, 0.2f, 1}, {0.2f, 0.8f, 0.3f, 1}, {0.3f, 0.4f, 0.9f, 1}};
  printf("display angle %d colour %d shape %d wire %d\n", angle, colour, shape, wire);
  fflush(stdout);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -6);
  glRotatef(25, 1, 0, 0);
  glRotatef((GLfloat)angle, 0, 1, 0);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colours[colour - 10]);
  if (shape == 20) {
    if (wire) glutWireCube(2.0); else glutSolidCube(2.0);
  } else if (shape == 21) {
    glFrontFace(GL_CW); /* the teapot's faces wind clockwise, as in GLUT 3.7 */
    if (wire) glutWireTeapot(1.1); else glutSolidTeapot(1.1);
    glFrontFace(GL_CCW);
  } else {
    if (wire) glutWireSphere(1.3, 24, 12); else glutSolidSphere(1.3, 24, 12);
  }
  glutSwapBuffers();
}

static void reshape(int w, int h)
{
  printf("reshape %d %d\n", w, h);
  fflush(stdout);
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)w / (double)(h ? h : 1), 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
}

static void idle(void)
{
  angle += 10;
  if (angle >= target) {
    angle = target;
    printf("idle stopped at %d\n", angle);
    fflush(stdout);
    glutIdleFunc(NULL);
  }
  glutPostRedisplay();
}

static void spin(void)
{
  target += 90;
  glutIdleFunc(idle);
}

static void keyboard(unsigned char key, int x, int y)
{
  printf("key %c at %d %d modifiers %d\n", key, x, y, glutGetModifiers());
  fflush(stdout);
  if (key == 's') spin();
  if (key == 'q') exit(0);
}

static void menuStatus(int status, int x, int y)
{
  printf("menu status %d at %d %d\n", status, x, y);
  fflush(stdout);
}

static void chooseMain(int value)
{
  printf("menu main %d, current menu is main %d, window %d\n", value, glutGetMenu() == mainMenu,
         glutGetWindow());
  fflush(stdout);
  if (value == 1) spin();
  if (value == 2) {
    wire = !wire;
    /* Entry 4 is this one: its label says what choosing it will do next. */
    glutChangeToMenuEntry(4, wire ? "Solid" : "Wireframe", 2);
    printf("menu items %d\n", glutGet(GLUT_MENU_NUM_ITEMS));
    fflush(stdout);
  }
  if (value == 99) exit(0);
  glutPostRedisplay();
}

static void chooseColour(int value)
{
  /* Not glutGetMenu here: GLUT 3.7 (6.1) makes the current menu the one whose entry was chosen,
   * but freeglut 3.4, with a menu status callback, leaves it at the main menu of the pop-up. */
  printf("menu colour %d\n", value);
  fflush(stdout);
  colour = value;
  glutPostRedisplay();
}

static void chooseShape(int value)
{
  printf("menu shape %d\n", value);
  fflush(stdout);
  shape = value;
  glutPostRedisplay();
}

int main(int argc, char** argv)
{
  static const GLfloat lightPosition[4] = {2, 3, 4, 0};
  int colourMenu, shapeMenu;
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  /* At the screen's corner: freeglut 3.4 on X11 finds the entry a release chooses from the
   * pointer's position in the window taken as a position on the screen (fgCheckActiveMenu), so
   * only there does dragging to an entry choose the entry under the pointer. */
  glutInitWindowPosition(0, 0);
  glutCreateWindow("spin menu");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutMenuStatusFunc(menuStatus);

  colourMenu = glutCreateMenu(chooseColour);
  glutAddMenuEntry("Red", 10);
  glutAddMenuEntry("Green", 11);
  glutAddMenuEntry("Blue", 12);
  shapeMenu = glutCreateMenu(chooseShape);
  glutAddMenuEntry("Cube", 20);
  glutAddMenuEntry("Teapot", 21);
  glutAddMenuEntry("Sphere", 22);
  mainMenu = glutCreateMenu(chooseMain);
  glutAddMenuEntry("Spin", 1);
  glutAddSubMenu("Colour", colourMenu);
  glutAddSubMenu("Shape", shapeMenu);
  glutAddMenuEntry("Wireframe", 2);
  glutAddMenuEntry("Quit", 99);
  glutAttachMenu(GLUT_RIGHT_BUTTON);
  printf("menus %d %d %d, items %d\n", colourMenu, shapeMenu, mainMenu,
         glutGet(GLUT_MENU_NUM_ITEMS));
  fflush(stdout);

  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glutMainLoop();
  return 0;
}
