/* glass: the GLUT geometry routines (GLUT 3.7 specification, chapter 11) and fonts (chapter 13).
 *
 * glass renders offscreen (see glass/context.h), so this header has no windows, menus or event
 * loop yet: only the shapes, drawn with the vertices, normals and vertex order of freeglut 3, and
 * the text, drawn with glass's own glyphs at freeglut 3's advances and line heights.
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

/* The fonts: handles that are the addresses of these variables, declared and defined as freeglut
 * does on Unix (freeglut_std.h), so that a program written for freeglut compiles unchanged. */
extern void* glutStrokeRoman;
extern void* glutStrokeMonoRoman;
extern void* glutBitmap9By15;
extern void* glutBitmap8By13;
extern void* glutBitmapTimesRoman10;
extern void* glutBitmapTimesRoman24;
extern void* glutBitmapHelvetica10;
extern void* glutBitmapHelvetica12;
extern void* glutBitmapHelvetica18;
#define  GLUT_STROKE_ROMAN               ((void *) &glutStrokeRoman)
#define  GLUT_STROKE_MONO_ROMAN          ((void *) &glutStrokeMonoRoman)
#define  GLUT_BITMAP_9_BY_15             ((void *) &glutBitmap9By15)
#define  GLUT_BITMAP_8_BY_13             ((void *) &glutBitmap8By13)
#define  GLUT_BITMAP_TIMES_ROMAN_10      ((void *) &glutBitmapTimesRoman10)
#define  GLUT_BITMAP_TIMES_ROMAN_24      ((void *) &glutBitmapTimesRoman24)
#define  GLUT_BITMAP_HELVETICA_10        ((void *) &glutBitmapHelvetica10)
#define  GLUT_BITMAP_HELVETICA_12        ((void *) &glutBitmapHelvetica12)
#define  GLUT_BITMAP_HELVETICA_18        ((void *) &glutBitmapHelvetica18)

/* Bitmap text: glBitmap at the current raster position, which moves by each character's advance
 * (glutBitmapWidth, pixels); the unpack state is pushed and popped around it. Characters 1 to
 * 255; glass's glyphs cover 32 to 126, other characters are blank but advance as freeglut's. */
GLAPI void GLAPIENTRY glutBitmapCharacter(void* font, int character);
GLAPI int GLAPIENTRY glutBitmapWidth(void* font, int character);
GLAPI int GLAPIENTRY glutBitmapLength(void* font, const unsigned char* string);
/* Stroke text: line strips in model units (capitals 100 tall), then glTranslatef by the
 * character's advance. Characters 32 to 127. */
GLAPI void GLAPIENTRY glutStrokeCharacter(void* font, int character);
GLAPI int GLAPIENTRY glutStrokeWidth(void* font, int character);
GLAPI int GLAPIENTRY glutStrokeLength(void* font, const unsigned char* string);
/* GLUT 3.8's and freeglut's additions: float widths, line heights, and whole strings, where '\n'
 * goes back to the line's start and down one line height. */
GLAPI GLfloat GLAPIENTRY glutStrokeWidthf(void* font, int character);
GLAPI GLfloat GLAPIENTRY glutStrokeLengthf(void* font, const unsigned char* string);
GLAPI int GLAPIENTRY glutBitmapHeight(void* font);
GLAPI GLfloat GLAPIENTRY glutStrokeHeight(void* font);
GLAPI void GLAPIENTRY glutBitmapString(void* font, const unsigned char* string);
GLAPI void GLAPIENTRY glutStrokeString(void* font, const unsigned char* string);

#ifdef __cplusplus
}
#endif

#endif /* GLASS_GL_GLUT_H */
