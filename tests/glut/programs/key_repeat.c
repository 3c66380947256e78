/* A held key's auto-repeat, as a game-like program sees it: GLUT 3.7 (and freeglut on X) report
 * each repeat as a release and a press, unless the window ignores repeats (glutIgnoreKeyRepeat,
 * one window's setting) or key repeat is off for all windows (glutSetKeyRepeat). The program
 * counts each key's presses and releases and whether they alternate, and 'p' prints the counts
 * ("1" or "several", since the number of repeats depends on how long the key was held). Keys:
 * 'i' ignore repeats in this window (again: do not), 'r' key repeat off, 'R' back to the
 * default, 'g' print what glutDeviceGet says here and in the second window. 'q' ends it. For
 * comparison with freeglut (xvfb_differential.sh). */
#include <stdio.h>
#include <stdlib.h>
#include <GL/glut.h>

#define KEYS 512 /* characters, then GLUT_KEY_* codes from 256 */
static int presses[KEYS], releases[KEYS], alternate[KEYS], down[KEYS];
static int mainWindow, secondWindow, ignoring = 0;

static void display(void)
{
  printf("display %d\n", glutGetWindow());
  fflush(stdout);
  glClearColor(glutGetWindow() == mainWindow ? 0.3f : 0.6f, 0.3f, 0.4f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glutSwapBuffers();
}

static void count(int key, int pressed)
{
  if (presses[key] == 0 && releases[key] == 0) alternate[key] = 1;
  if (pressed == down[key]) alternate[key] = 0; /* two presses, or two releases, in a row */
  down[key] = pressed;
  if (pressed) ++presses[key]; else ++releases[key];
}

static const char* howMany(int n)
{
  return n == 0 ? "0" : n == 1 ? "1" : "several";
}

static void printCounts(void)
{
  int key;
  for (key = 0; key < KEYS; ++key) {
    if (presses[key] == 0 && releases[key] == 0) continue;
    if (key < 256) printf("key %c", key); else printf("special %d", key - 256);
    printf(": presses %s, releases %s, alternating %d\n", howMany(presses[key]),
           howMany(releases[key]), alternate[key]);
    presses[key] = releases[key] = down[key] = 0;
  }
  printf("counted\n");
  fflush(stdout);
}

static void printDevice(void)
{
  int window = glutGetWindow();
  printf("ignore key repeat %d, key repeat %d;", glutDeviceGet(GLUT_DEVICE_IGNORE_KEY_REPEAT),
         glutDeviceGet(GLUT_DEVICE_KEY_REPEAT));
  glutSetWindow(secondWindow);
  printf(" in the second window: ignore key repeat %d\n",
         glutDeviceGet(GLUT_DEVICE_IGNORE_KEY_REPEAT));
  fflush(stdout);
  glutSetWindow(window);
}

static void keyboard(unsigned char key, int x, int y)
{
  switch (key) {
    case 'p': printCounts(); return;
    case 'i': ignoring = !ignoring; glutIgnoreKeyRepeat(ignoring); printDevice(); return;
    case 'r': glutSetKeyRepeat(GLUT_KEY_REPEAT_OFF); printDevice(); return;
    case 'R': glutSetKeyRepeat(GLUT_KEY_REPEAT_DEFAULT); printDevice(); return;
    case 'g': printDevice(); return;
    case 'q': exit(0);
  }
  count(key, 1);
}

static void keyboardUp(unsigned char key, int x, int y)
{
  if (key == 'a' || key == 'b' || key == 'c' || key == 'd') count(key, 0);
}

static void special(int key, int x, int y)
{
  if (key >= 0 && key < 256) count(256 + key, 1);
}

static void specialUp(int key, int x, int y)
{
  if (key >= 0 && key < 256) count(256 + key, 0);
}

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(200, 150);
  glutInitWindowPosition(0, 0);
  mainWindow = glutCreateWindow("key repeat");
  glutDisplayFunc(display);
  glutKeyboardFunc(keyboard);
  glutKeyboardUpFunc(keyboardUp);
  glutSpecialFunc(special);
  glutSpecialUpFunc(specialUp);
  glutInitWindowPosition(300, 0);
  secondWindow = glutCreateWindow("second window");
  glutDisplayFunc(display);
  glutSetWindow(mainWindow);
  glutMainLoop();
  return 0;
}
