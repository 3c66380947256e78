// glutSolidTeapot, glutSolidTeacup, glutSolidTeaspoon and their wire forms: the Utah teaset,
// tessellated as freeglut 3 tessellates it (glut/teaset_mesh.cpp) so that a program draws the
// same picture with glass as with freeglut, and sent to the GL like the other GLUT shapes. As in
// freeglut, each piece has y up; the teapot is centred on the origin with its spout towards +x
// (its height is about 1.575 size), the teacup stands upright about the origin with its handle
// towards -x and the teaspoon lies along the z axis, to the teapot's scale for the same size.
#include <GL/glut.h>

#include "glut/shape_mesh.h"

namespace {

void draw(glass::gl::glut::ShapeMesh (*mesh)(float, bool), GLdouble size, bool wire) {
  glass::gl::glut::drawShapeMesh(mesh(static_cast<float>(size), wire));
}

}  // namespace

extern "C" {

void glutSolidTeapot(GLdouble size) { draw(glass::gl::glut::teapotMesh, size, false); }
void glutWireTeapot(GLdouble size) { draw(glass::gl::glut::teapotMesh, size, true); }
void glutSolidTeacup(GLdouble size) { draw(glass::gl::glut::teacupMesh, size, false); }
void glutWireTeacup(GLdouble size) { draw(glass::gl::glut::teacupMesh, size, true); }
void glutSolidTeaspoon(GLdouble size) { draw(glass::gl::glut::teaspoonMesh, size, false); }
void glutWireTeaspoon(GLdouble size) { draw(glass::gl::glut::teaspoonMesh, size, true); }

}  // extern "C"
