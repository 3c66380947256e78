/* glass: the GLUT geometry routines (GLUT 3.7 specification, chapter 11).
 *
 * glass renders offscreen (see glass/context.h), so this header has no windows, menus or event
 * loop yet: only the shapes, drawn with the vertices, normals and vertex order of freeglut 3.
 * Sizes: the sphere and cone have the given radius/base and height along +z from z = 0 (the cone)
 * or centred at the origin (the sphere); the cube has edge `size`; the tetrahedron, octahedron
 * and icosahedron have circumradius 1, the dodecahedron sqrt(3). glutSolidCylinder and
 * glutWireCylinder are freeglut's additions.
 */
#ifndef GLASS_GL_GLUT_H
#define GLASS_GL_GLUT_H

#include <GL/gl.h>
#include <GL/glu.h>

#ifdef __cplusplus
extern "C" {
#endif

GLAPI void GLAPIENTRY glutSolidSphere(GLdouble radius, GLint slices, GLint stacks);
GLAPI void GLAPIENTRY glutWireSphere(GLdouble radius, GLint slices, GLint stacks);
GLAPI void GLAPIENTRY glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
GLAPI void GLAPIENTRY glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
GLAPI void GLAPIENTRY glutSolidCylinder(GLdouble radius, GLdouble height, GLint slices, GLint stacks);
GLAPI void GLAPIENTRY glutWireCylinder(GLdouble radius, GLdouble height, GLint slices, GLint stacks);
GLAPI void GLAPIENTRY glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
GLAPI void GLAPIENTRY glutWireTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
GLAPI void GLAPIENTRY glutSolidCube(GLdouble size);
GLAPI void GLAPIENTRY glutWireCube(GLdouble size);
GLAPI void GLAPIENTRY glutSolidTetrahedron(void);
GLAPI void GLAPIENTRY glutWireTetrahedron(void);
GLAPI void GLAPIENTRY glutSolidOctahedron(void);
GLAPI void GLAPIENTRY glutWireOctahedron(void);
GLAPI void GLAPIENTRY glutSolidDodecahedron(void);
GLAPI void GLAPIENTRY glutWireDodecahedron(void);
GLAPI void GLAPIENTRY glutSolidIcosahedron(void);
GLAPI void GLAPIENTRY glutWireIcosahedron(void);
/* freeglut's additions: the rhombic dodecahedron (corners at distance 1 on the axes) and the
 * Sierpinski sponge (num_levels subdivisions of a tetrahedron of circumradius `scale` at
 * `offset`). */
GLAPI void GLAPIENTRY glutSolidRhombicDodecahedron(void);
GLAPI void GLAPIENTRY glutWireRhombicDodecahedron(void);
GLAPI void GLAPIENTRY glutSolidSierpinskiSponge(int num_levels, double offset[3], double scale);
GLAPI void GLAPIENTRY glutWireSierpinskiSponge(int num_levels, double offset[3], double scale);
/* The Utah teapot, about 1.575 size tall and centred on the origin, y up, spout towards +x,
 * tessellated exactly as freeglut 3 does it (32 bicubic patches on 8 x 8 points solid, as
 * triangles with texture coordinates; 10 x 10 wire, as line strips). */
GLAPI void GLAPIENTRY glutSolidTeapot(GLdouble size);
GLAPI void GLAPIENTRY glutWireTeapot(GLdouble size);

#ifdef __cplusplus
}
#endif

#endif /* GLASS_GL_GLUT_H */
