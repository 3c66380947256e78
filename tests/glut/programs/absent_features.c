/* GLUT's calls for what glass's windows do not have: they compile, link and answer as freeglut
 * does without the hardware. argv[1] "core" asks for an OpenGL 3.3 core context first, which
 * glass cannot make. Prints what each query answers; exits 0 after the first frame. */
#include <stdio.h>
#include <string.h>
#include <GL/freeglut.h>

static int calls;

static void joystick(unsigned int buttons, int x, int y, int z) { ++calls; }
static void twoInts(int a, int b) { ++calls; }
static void threeInts(int a, int b, int c) { ++calls; }
static void fourInts(int a, int b, int c, int d) { ++calls; }
static void fiveInts(int a, int b, int c, int d, int e) { ++calls; }
static void noArguments(void) { ++calls; }
static void menu(int value) {}

static void display(void)
{
  glClear(GL_COLOR_BUFFER_BIT);
  glutSwapBuffers();
  printf("device callbacks called %d times\n", calls);
}

int main(int argc, char **argv)
{
  int size = -1, *values;
  glutInit(&argc, argv);
  if (argc > 1 && strcmp(argv[1], "core") == 0) {
    glutInitContextVersion(3, 3);
    glutInitContextProfile(GLUT_CORE_PROFILE);
  } else {
    glutInitContextVersion(1, 4);
  }
  printf("asked %d.%d flags %d profile %d\n", glutGet(GLUT_INIT_MAJOR_VERSION),
         glutGet(GLUT_INIT_MINOR_VERSION), glutGet(GLUT_INIT_FLAGS), glutGet(GLUT_INIT_PROFILE));
  fflush(stdout);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutCreateWindow("absent features");
  glutDisplayFunc(display);
  glutJoystickFunc(joystick, 10);
  glutForceJoystickFunc();
  glutSpaceballMotionFunc(threeInts);
  glutSpaceballRotateFunc(threeInts);
  glutSpaceballButtonFunc(twoInts);
  glutButtonBoxFunc(twoInts);
  glutDialsFunc(twoInts);
  glutTabletMotionFunc(twoInts);
  glutTabletButtonFunc(fourInts);
  glutMultiEntryFunc(twoInts);
  glutMultiButtonFunc(fiveInts);
  glutMultiMotionFunc(threeInts);
  glutMultiPassiveFunc(threeInts);
  glutOverlayDisplayFunc(noArguments);
  glutInitContextFunc(noArguments);
  glutAppStatusFunc(menu);
  glutEstablishOverlay();
  glutUseLayer(GLUT_OVERLAY);
  glutPostOverlayRedisplay();
  glutShowOverlay();
  glutHideOverlay();
  glutUseLayer(GLUT_NORMAL);
  glutRemoveOverlay();
  glutSetColor(1, 1.0f, 0.0f, 0.0f);
  values = glutGetModeValues(GLUT_MULTISAMPLE, &size);
  printf("overlay possible %d, colour %g, video resize %d, multisample values %s %d\n",
         glutLayerGet(GLUT_OVERLAY_POSSIBLE), glutGetColor(1, GLUT_RED),
         glutVideoResizeGet(GLUT_VIDEO_RESIZE_POSSIBLE), values ? "some" : "none", size);
  printf("proc glutSwapBuffers %s, glActiveTexture %s, gluPerspective %s, glutNoSuch %s\n",
         glutGetProcAddress("glutSwapBuffers") == (GLUTproc)glutSwapBuffers ? "found" : "missing",
         glutGetProcAddress("glActiveTexture") ? "found" : "missing",
         glutGetProcAddress("gluPerspective") ? "found" : "missing",
         glutGetProcAddress("glutNoSuch") ? "found" : "missing");
  /* Options kept and read back as set, with freeglut's defaults: they change nothing here. */
  printf("options: rendering context %d, direct %d, skip stale motion %d",
         glutGet(GLUT_RENDERING_CONTEXT), glutGet(GLUT_DIRECT_RENDERING),
         glutGet(GLUT_SKIP_STALE_MOTION_EVENTS));
  glutSetOption(GLUT_RENDERING_CONTEXT, GLUT_USE_CURRENT_CONTEXT);
  glutSetOption(GLUT_DIRECT_RENDERING, GLUT_FORCE_INDIRECT_CONTEXT);
  glutSetOption(GLUT_SKIP_STALE_MOTION_EVENTS, 1);
  printf(" -> %d, %d, %d\n", glutGet(GLUT_RENDERING_CONTEXT), glutGet(GLUT_DIRECT_RENDERING),
         glutGet(GLUT_SKIP_STALE_MOTION_EVENTS));
  glutSetMenuFont(glutCreateMenu(menu), GLUT_BITMAP_9_BY_15);
  glutSetMenuFont(glutGetMenu(), GLUT_STROKE_ROMAN);
  fflush(stdout);
  glutMainLoop();
  return 0;
}
