/* The study guide's Listing 5 (section 2.2.2, recursive Sierpinski triangle) as printed, with
 * Listing 4's drawFractal in its place; only the header name is spelled for Linux. */
#include <stdlib.h>
#include <stdio.h>
#include <GL/glut.h>

int CurrentStep = 0;
const int MaxStep = 10;
const double Xmin = -0.1, Xmax = 1.1;
const double Ymin = -0.1, Ymax = 1.1;

void myKeyboardFunc(unsigned char key, int x, int y)
{
  switch (key) {
  case ' ':
    CurrentStep = (CurrentStep+1)%MaxStep;
    glutPostRedisplay();
    break;
  case 27:
    exit(1);
  }
}

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

int main(int argc, char** argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowPosition(20, 60);
  glutInitWindowSize(500, 500);
  glutCreateWindow("Sierpinski triangle");
  initRendering();
  glutKeyboardFunc(myKeyboardFunc);
  glutReshapeFunc(resizeWindow);
  glutDisplayFunc(drawScene);
  fprintf(stdout, "Press space bar -> the next step; esc -> to quit.\n");
  glutMainLoop();
  return(0);
}
