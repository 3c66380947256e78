// The GLUT geometry entry points (GLUT 3.7 specification, chapter 11, and freeglut's
// cylinder, rhombic dodecahedron and Sierpinski sponge). Sizes arrive as double and are used in float, as freeglut does.
#include <GL/freeglut.h>

#include "glut/shape_mesh.h"

using glass::gl::glut::drawShapeMesh;
namespace shapes = glass::gl::glut;

namespace {
float toFloat(double v) { return static_cast<float>(v); }
}  // namespace

extern "C" {

void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks) {
  drawShapeMesh(shapes::sphereMesh(toFloat(radius), slices, stacks, false));
}
void glutWireSphere(GLdouble radius, GLint slices, GLint stacks) {
  drawShapeMesh(shapes::sphereMesh(toFloat(radius), slices, stacks, true));
}
void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks) {
  drawShapeMesh(shapes::coneMesh(toFloat(base), toFloat(height), slices, stacks, false));
}
void glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks) {
  drawShapeMesh(shapes::coneMesh(toFloat(base), toFloat(height), slices, stacks, true));
}
void glutSolidCylinder(GLdouble radius, GLdouble height, GLint slices, GLint stacks) {
  drawShapeMesh(shapes::cylinderMesh(toFloat(radius), toFloat(height), slices, stacks, false));
}
void glutWireCylinder(GLdouble radius, GLdouble height, GLint slices, GLint stacks) {
  drawShapeMesh(shapes::cylinderMesh(toFloat(radius), toFloat(height), slices, stacks, true));
}
void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings) {
  drawShapeMesh(shapes::torusMesh(toFloat(innerRadius), toFloat(outerRadius), sides, rings, false));
}
void glutWireTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings) {
  drawShapeMesh(shapes::torusMesh(toFloat(innerRadius), toFloat(outerRadius), sides, rings, true));
}
void glutSolidCube(GLdouble size) { drawShapeMesh(shapes::cubeMesh(toFloat(size), false)); }
void glutWireCube(GLdouble size) { drawShapeMesh(shapes::cubeMesh(toFloat(size), true)); }
void glutSolidTetrahedron(void) { drawShapeMesh(shapes::tetrahedronMesh(false)); }
void glutWireTetrahedron(void) { drawShapeMesh(shapes::tetrahedronMesh(true)); }
void glutSolidOctahedron(void) { drawShapeMesh(shapes::octahedronMesh(false)); }
void glutWireOctahedron(void) { drawShapeMesh(shapes::octahedronMesh(true)); }
void glutSolidDodecahedron(void) { drawShapeMesh(shapes::dodecahedronMesh(false)); }
void glutWireDodecahedron(void) { drawShapeMesh(shapes::dodecahedronMesh(true)); }
void glutSolidIcosahedron(void) { drawShapeMesh(shapes::icosahedronMesh(false)); }
void glutWireIcosahedron(void) { drawShapeMesh(shapes::icosahedronMesh(true)); }
void glutSolidRhombicDodecahedron(void) {
  drawShapeMesh(shapes::rhombicDodecahedronMesh(false));
}
void glutWireRhombicDodecahedron(void) { drawShapeMesh(shapes::rhombicDodecahedronMesh(true)); }
void glutSolidSierpinskiSponge(int levels, double offset[3], GLdouble scale) {
  if (offset) drawShapeMesh(shapes::sierpinskiSpongeMesh(levels, offset, toFloat(scale), false));
}
void glutWireSierpinskiSponge(int levels, double offset[3], GLdouble scale) {
  if (offset) drawShapeMesh(shapes::sierpinskiSpongeMesh(levels, offset, toFloat(scale), true));
}

// freeglut draws its shapes through these shader attributes in OpenGL 3 core contexts; glass's
// shapes go through the fixed-function arrays, so the attributes are not used.
void glutSetVertexAttribCoord3(GLint) {}
void glutSetVertexAttribNormal(GLint) {}
void glutSetVertexAttribTexCoord2(GLint) {}

}  // extern "C"
