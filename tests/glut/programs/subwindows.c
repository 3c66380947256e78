/* Sub-windows as the classic teaching programs lay them out (a main window cut into a "world"
 * view and a "command" view, each a sub-window with its own context and callbacks): a grey main
 * window 300 x 200 with a green sub-window on its left (10, 10, 130 x 180) and a blue one on its
 * right (150, 10, 140 x 180) that holds a smaller red one (20, 100, 50 x 40) of its own, and a
 * yellow 20 x 20 one placed 10 pixels from the main window's bottom-right corner by negative
 * coordinates (freeglut's rule). Each
 * window's input callbacks print the window and the coordinates they get; the main window's
 * reshape callback lays the sub-windows out again, as those programs do. The key `p` moves the
 * red sub-window, `h` hides it, `d` destroys the green one; `q` quits. */
#include <stdio.h>
#include <stdlib.h>
#include <GL/freeglut.h>

static int mainWindow, world, command, inset, corner;

static void clearTo(float r, float g, float b)
{
  glClearColor(r, g, b, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}

static void displayMain(void)
{
  clearTo(0.5f, 0.5f, 0.5f);
  glutSwapBuffers();
}

static void displayWorld(void)
{
  clearTo(0, 0.6f, 0);
  /* A white triangle in the lower half, to show the sub-window's own viewport and rows. */
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.5f, -0.9f);
  glVertex2f(0.5f, -0.9f);
  glVertex2f(0.0f, -0.1f);
  glEnd();
  glutSwapBuffers();
}

static void displayCommand(void)
{
  clearTo(0, 0, 0.6f);
  glutSwapBuffers();
}

static void displayInset(void)
{
  clearTo(0.8f, 0, 0);
  glutSwapBuffers();
}

static void displayCorner(void)
{
  clearTo(1, 1, 0);
  glutSwapBuffers();
}

static void reshapeMain(int width, int height)
{
  glViewport(0, 0, width, height);
  printf("reshape main %d %d\n", width, height);
  if (world) {
    glutSetWindow(world);
    glutPositionWindow(10, 10);
    glutReshapeWindow(width / 2 - 20, height - 20);
  }
  glutSetWindow(command);
  glutPositionWindow(width / 2, 10);
  glutReshapeWindow(width / 2 - 10, height - 20);
}

static void mouse(int button, int state, int x, int y)
{
  printf("mouse window %d button %d %s at %d %d\n", glutGetWindow(), button,
         state == GLUT_DOWN ? "down" : "up", x, y);
}

static void motion(int x, int y) { printf("motion window %d at %d %d\n", glutGetWindow(), x, y); }

static void entry(int state)
{
  printf("entry window %d %s\n", glutGetWindow(), state == GLUT_ENTERED ? "entered" : "left");
}

static void keyboard(unsigned char key, int x, int y)
{
  printf("key %c window %d at %d %d\n", key, glutGetWindow(), x, y);
  switch (key) {
    case 'p':
      glutSetWindow(inset);
      glutPositionWindow(60, 20);
      break;
    case 'h':
      glutSetWindow(inset);
      glutHideWindow();
      break;
    case 'd':
      glutDestroyWindow(world);
      world = 0;
      break;
    case 'q': exit(0);
  }
}

static void inputCallbacks(void)
{
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  glutEntryFunc(entry);
  glutKeyboardFunc(keyboard);
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(300, 200);
  mainWindow = glutCreateWindow("sub-windows");
  glutDisplayFunc(displayMain);
  glutReshapeFunc(reshapeMain);
  inputCallbacks();
  world = glutCreateSubWindow(mainWindow, 10, 10, 130, 180);
  glutDisplayFunc(displayWorld);
  inputCallbacks();
  command = glutCreateSubWindow(mainWindow, 150, 10, 140, 180);
  glutDisplayFunc(displayCommand);
  inputCallbacks();
  inset = glutCreateSubWindow(command, 20, 100, 50, 40);
  glutDisplayFunc(displayInset);
  inputCallbacks();
  corner = glutCreateSubWindow(mainWindow, -10, -10, 20, 20);
  glutDisplayFunc(displayCorner);
  printf("corner %d at %d %d, a sub-window of no window: %d\n", corner, glutGet(GLUT_WINDOW_X),
         glutGet(GLUT_WINDOW_Y), glutCreateSubWindow(99, 0, 0, 10, 10));
  glutSetWindow(inset);
  {
    const int parent = glutGet(GLUT_WINDOW_PARENT);
    glutSetWindow(mainWindow);
    printf("windows %d %d %d %d; parent of %d is %d, %d has %d children\n", mainWindow, world,
           command, inset, inset, parent, mainWindow, glutGet(GLUT_WINDOW_NUM_CHILDREN));
  }
  glutMainLoop();
  return 0;
}
