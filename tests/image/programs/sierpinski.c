/* The study guide's recursive Sierpinski triangle (section 2.2.2, Listings 4 and 5).
 *
 * drawFractal, drawScene, initRendering and resizeWindow are as printed in the guide. What GLUT
 * did is done by hand: the window is a 640 x 480 glass context (not square, so that
 * resizeWindow's aspect correction matters), the display callback runs once, and the step is
 * fixed at 6 instead of being chosen with the space bar. */
#include <GL/gl.h>

#include "gl_program.h"

int CurrentStep = 6;
const double Xmin = -0.1, Xmax = 1.1;
const double Ymin = -0.1, Ymax = 1.1;

void drawFractal(int step)
{
  switch (step) {
  case 0:
    glBegin(GL_TRIANGLES);
    glVertex3f(1.0, 0.0, 0.0);
    glVertex3f(0.0, 1.0, 0.0);
    glVertex3f(0.0, 0.0, 0.0);
    glEnd();
    break;
  default:
    glPushMatrix();
    glPushMatrix();
    glScalef(0.5, 0.5, 1.0);
    drawFractal(step-1);
    glPopMatrix();
    glTranslatef(0.5, 0.0, 0.0);
    glScalef(0.5, 0.5, 1.0);
    drawFractal(step-1);
    glPopMatrix();
    glTranslatef(0.0, 0.5, 0.0);
    glScalef(0.5, 0.5, 1.0);
    drawFractal(step-1);
    break;
  }
}

void drawScene(void)
{
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1.0, 1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  drawFractal(CurrentStep);
  glFlush();
}

void initRendering()
{
  glEnable(GL_DEPTH_TEST);
}

void resizeWindow(int w, int h)
{
  double scale, center;
  double windowXmin, windowXmax, windowYmin, windowYmax;
  glViewport(0, 0, w, h);
  w = (w==0) ? 1 : w;
  h = (h==0) ? 1 : h;
  if ((Xmax-Xmin)/w < (Ymax-Ymin)/h) {
    scale = ((Ymax-Ymin)/h) / ((Xmax-Xmin)/w);
    center = (Xmax+Xmin)/2;
    windowXmin = center - (center-Xmin)*scale;
    windowXmax = center + (Xmax-center)*scale;
    windowYmin = Ymin;
    windowYmax = Ymax;
  }
  else {
    scale = ((Xmax-Xmin)/w) / ((Ymax-Ymin)/h);
    center = (Ymax+Ymin)/2;
    windowYmin = center - (center-Ymin)*scale;
    windowYmax = center + (Ymax-center)*scale;
    windowXmin = Xmin;
    windowXmax = Xmax;
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(windowXmin, windowXmax, windowYmin, windowYmax, -1, 1);
}

enum { WIDTH = 640, HEIGHT = 480 };

/* The order GLUT calls the listing's functions in: initRendering before the main loop, then the
 * reshape callback for the new window, then the display callback. */
static void draw(void)
{
  initRendering();
  resizeWindow(WIDTH, HEIGHT);
  drawScene();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
