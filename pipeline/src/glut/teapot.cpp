// glutSolidTeapot and glutWireTeapot: the Utah teapot, tessellated as freeglut 3 tessellates it
// (glut/teapot_mesh.cpp) so that a program draws the same picture with glass as with freeglut,
// and sent to the GL like the other GLUT shapes. Like freeglut's, the teapot is centred on the
// origin with y up and the spout towards +x; `size` scales it (its height is about 1.575 size).
#include <GL/glut.h>

#include "glut/shape_mesh.h"

extern "C" {

void glutSolidTeapot(GLdouble size) {
  glass::gl::glut::drawShapeMesh(glass::gl::glut::teapotMesh(static_cast<float>(size), false));
}

void glutWireTeapot(GLdouble size) {
  glass::gl::glut::drawShapeMesh(glass::gl::glut::teapotMesh(static_cast<float>(size), true));
}

}  // extern "C"
