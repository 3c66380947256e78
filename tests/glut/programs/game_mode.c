/* Game mode: argv[1] is the game mode string. Prints what glutGameModeGet says before and after
 * glutEnterGameMode; the game mode window draws a red square on blue. The key `l` leaves game
 * mode (which destroys its window, so the program ends), `e` enters it again (a new window). */
#include <stdio.h>
#include <GL/glut.h>

static void display(void)
{
  glClearColor(0, 0, 0.6f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  glutSwapBuffers();
}

static void report(const char *when)
{
  printf("%s: active %d possible %d %d x %d depth %d refresh %d changed %d\n", when,
         glutGameModeGet(GLUT_GAME_MODE_ACTIVE), glutGameModeGet(GLUT_GAME_MODE_POSSIBLE),
         glutGameModeGet(GLUT_GAME_MODE_WIDTH), glutGameModeGet(GLUT_GAME_MODE_HEIGHT),
         glutGameModeGet(GLUT_GAME_MODE_PIXEL_DEPTH),
         glutGameModeGet(GLUT_GAME_MODE_REFRESH_RATE),
         glutGameModeGet(GLUT_GAME_MODE_DISPLAY_CHANGED));
}

static void enter(void);

static void keyboard(unsigned char key, int x, int y)
{
  if (key == 'l') {
    glutLeaveGameMode();
    report("left");
  } else if (key == 'e') {
    enter();
  }
}

static void enter(void)
{
  const int window = glutEnterGameMode();
  printf("window %d, %d x %d at %d %d\n", window, glutGet(GLUT_WINDOW_WIDTH),
         glutGet(GLUT_WINDOW_HEIGHT), glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y));
  glutDisplayFunc(display);
  glutKeyboardFunc(keyboard);
  report("entered");
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  if (argc > 1) glutGameModeString(argv[1]);
  report("before");
  enter();
  glutMainLoop();
  return 0;
}
