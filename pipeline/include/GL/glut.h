/* glass: GLUT 3.7 (the specification's chapters 2-13) over SDL2: windows, the event loop,
 * callbacks, pop-up menus drawn by glass, the geometry routines and the fonts. freeglut's own
 * additions (glutMainLoopEvent, glutLeaveMainLoop, glutSetOption, glutCloseFunc, ...) are in
 * <GL/freeglut.h>. docs/glut.md says what is implemented and how it differs from freeglut; the
 * names and values below are freeglut 3's, so a program written for freeglut compiles unchanged.
 *
 * The shapes are drawn with the vertices, normals and vertex order of freeglut 3, and the text
 * with glass's own glyphs at freeglut 3's advances and line heights.
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

/* Special keys (glutSpecialFunc), mouse buttons and states, entry and visibility states. */
#define  GLUT_KEY_F1                        0x0001
#define  GLUT_KEY_F2                        0x0002
#define  GLUT_KEY_F3                        0x0003
#define  GLUT_KEY_F4                        0x0004
#define  GLUT_KEY_F5                        0x0005
#define  GLUT_KEY_F6                        0x0006
#define  GLUT_KEY_F7                        0x0007
#define  GLUT_KEY_F8                        0x0008
#define  GLUT_KEY_F9                        0x0009
#define  GLUT_KEY_F10                       0x000A
#define  GLUT_KEY_F11                       0x000B
#define  GLUT_KEY_F12                       0x000C
#define  GLUT_KEY_LEFT                      0x0064
#define  GLUT_KEY_UP                        0x0065
#define  GLUT_KEY_RIGHT                     0x0066
#define  GLUT_KEY_DOWN                      0x0067
#define  GLUT_KEY_PAGE_UP                   0x0068
#define  GLUT_KEY_PAGE_DOWN                 0x0069
#define  GLUT_KEY_HOME                      0x006A
#define  GLUT_KEY_END                       0x006B
#define  GLUT_KEY_INSERT                    0x006C
#define  GLUT_LEFT_BUTTON                   0x0000
#define  GLUT_MIDDLE_BUTTON                 0x0001
#define  GLUT_RIGHT_BUTTON                  0x0002
#define  GLUT_DOWN                          0x0000
#define  GLUT_UP                            0x0001
#define  GLUT_LEFT                          0x0000
#define  GLUT_ENTERED                       0x0001

/* Display modes (glutInitDisplayMode). glass's framebuffer is always RGBA with depth, stencil
 * and accumulation buffers; GLUT_INDEX, GLUT_STEREO and GLUT_MULTISAMPLE cannot be had. */
#define  GLUT_RGB                           0x0000
#define  GLUT_RGBA                          0x0000
#define  GLUT_INDEX                         0x0001
#define  GLUT_SINGLE                        0x0000
#define  GLUT_DOUBLE                        0x0002
#define  GLUT_ACCUM                         0x0004
#define  GLUT_ALPHA                         0x0008
#define  GLUT_DEPTH                         0x0010
#define  GLUT_STENCIL                       0x0020
#define  GLUT_MULTISAMPLE                   0x0080
#define  GLUT_STEREO                        0x0100
#define  GLUT_LUMINANCE                     0x0200

#define  GLUT_MENU_NOT_IN_USE               0x0000
#define  GLUT_MENU_IN_USE                   0x0001
#define  GLUT_NOT_VISIBLE                   0x0000
#define  GLUT_VISIBLE                       0x0001
#define  GLUT_HIDDEN                        0x0000
#define  GLUT_FULLY_RETAINED                0x0001
#define  GLUT_PARTIALLY_RETAINED            0x0002
#define  GLUT_FULLY_COVERED                 0x0003

/* glutGet, glutDeviceGet and glutLayerGet queries. */
#define  GLUT_WINDOW_X                      0x0064
#define  GLUT_WINDOW_Y                      0x0065
#define  GLUT_WINDOW_WIDTH                  0x0066
#define  GLUT_WINDOW_HEIGHT                 0x0067
#define  GLUT_WINDOW_BUFFER_SIZE            0x0068
#define  GLUT_WINDOW_STENCIL_SIZE           0x0069
#define  GLUT_WINDOW_DEPTH_SIZE             0x006A
#define  GLUT_WINDOW_RED_SIZE               0x006B
#define  GLUT_WINDOW_GREEN_SIZE             0x006C
#define  GLUT_WINDOW_BLUE_SIZE              0x006D
#define  GLUT_WINDOW_ALPHA_SIZE             0x006E
#define  GLUT_WINDOW_ACCUM_RED_SIZE         0x006F
#define  GLUT_WINDOW_ACCUM_GREEN_SIZE       0x0070
#define  GLUT_WINDOW_ACCUM_BLUE_SIZE        0x0071
#define  GLUT_WINDOW_ACCUM_ALPHA_SIZE       0x0072
#define  GLUT_WINDOW_DOUBLEBUFFER           0x0073
#define  GLUT_WINDOW_RGBA                   0x0074
#define  GLUT_WINDOW_PARENT                 0x0075
#define  GLUT_WINDOW_NUM_CHILDREN           0x0076
#define  GLUT_WINDOW_COLORMAP_SIZE          0x0077
#define  GLUT_WINDOW_NUM_SAMPLES            0x0078
#define  GLUT_WINDOW_STEREO                 0x0079
#define  GLUT_WINDOW_CURSOR                 0x007A
#define  GLUT_SCREEN_WIDTH                  0x00C8
#define  GLUT_SCREEN_HEIGHT                 0x00C9
#define  GLUT_SCREEN_WIDTH_MM               0x00CA
#define  GLUT_SCREEN_HEIGHT_MM              0x00CB
#define  GLUT_MENU_NUM_ITEMS                0x012C
#define  GLUT_DISPLAY_MODE_POSSIBLE         0x0190
#define  GLUT_INIT_WINDOW_X                 0x01F4
#define  GLUT_INIT_WINDOW_Y                 0x01F5
#define  GLUT_INIT_WINDOW_WIDTH             0x01F6
#define  GLUT_INIT_WINDOW_HEIGHT            0x01F7
#define  GLUT_INIT_DISPLAY_MODE             0x01F8
#define  GLUT_ELAPSED_TIME                  0x02BC
#define  GLUT_WINDOW_FORMAT_ID              0x007B
#define  GLUT_HAS_KEYBOARD                  0x0258
#define  GLUT_HAS_MOUSE                     0x0259
#define  GLUT_HAS_SPACEBALL                 0x025A
#define  GLUT_HAS_DIAL_AND_BUTTON_BOX       0x025B
#define  GLUT_HAS_TABLET                    0x025C
#define  GLUT_NUM_MOUSE_BUTTONS             0x025D
#define  GLUT_NUM_SPACEBALL_BUTTONS         0x025E
#define  GLUT_NUM_BUTTON_BOX_BUTTONS        0x025F
#define  GLUT_NUM_DIALS                     0x0260
#define  GLUT_NUM_TABLET_BUTTONS            0x0261
#define  GLUT_DEVICE_IGNORE_KEY_REPEAT      0x0262
#define  GLUT_DEVICE_KEY_REPEAT             0x0263
#define  GLUT_HAS_JOYSTICK                  0x0264
#define  GLUT_OWNS_JOYSTICK                 0x0265
#define  GLUT_JOYSTICK_BUTTONS              0x0266
#define  GLUT_JOYSTICK_AXES                 0x0267
#define  GLUT_JOYSTICK_POLL_RATE            0x0268
#define  GLUT_OVERLAY_POSSIBLE              0x0320
#define  GLUT_LAYER_IN_USE                  0x0321
#define  GLUT_HAS_OVERLAY                   0x0322
#define  GLUT_TRANSPARENT_INDEX             0x0323
#define  GLUT_NORMAL_DAMAGED                0x0324
#define  GLUT_OVERLAY_DAMAGED               0x0325
#define  GLUT_NORMAL                        0x0000
#define  GLUT_OVERLAY                       0x0001

/* glutGetColor components. */
#define  GLUT_RED                           0x0000
#define  GLUT_GREEN                         0x0001
#define  GLUT_BLUE                          0x0002

/* glutVideoResizeGet queries. */
#define  GLUT_VIDEO_RESIZE_POSSIBLE         0x0384
#define  GLUT_VIDEO_RESIZE_IN_USE           0x0385
#define  GLUT_VIDEO_RESIZE_X_DELTA          0x0386
#define  GLUT_VIDEO_RESIZE_Y_DELTA          0x0387
#define  GLUT_VIDEO_RESIZE_WIDTH_DELTA      0x0388
#define  GLUT_VIDEO_RESIZE_HEIGHT_DELTA     0x0389
#define  GLUT_VIDEO_RESIZE_X                0x038A
#define  GLUT_VIDEO_RESIZE_Y                0x038B
#define  GLUT_VIDEO_RESIZE_WIDTH            0x038C
#define  GLUT_VIDEO_RESIZE_HEIGHT           0x038D

/* glutGameModeGet queries. */
#define  GLUT_GAME_MODE_ACTIVE              0x0000
#define  GLUT_GAME_MODE_POSSIBLE            0x0001
#define  GLUT_GAME_MODE_WIDTH               0x0002
#define  GLUT_GAME_MODE_HEIGHT              0x0003
#define  GLUT_GAME_MODE_PIXEL_DEPTH         0x0004
#define  GLUT_GAME_MODE_REFRESH_RATE        0x0005
#define  GLUT_GAME_MODE_DISPLAY_CHANGED     0x0006

/* glutGetModifiers. */
#define  GLUT_ACTIVE_SHIFT                  0x0001
#define  GLUT_ACTIVE_CTRL                   0x0002
#define  GLUT_ACTIVE_ALT                    0x0004

/* glutSetCursor. */
#define  GLUT_CURSOR_RIGHT_ARROW            0x0000
#define  GLUT_CURSOR_LEFT_ARROW             0x0001
#define  GLUT_CURSOR_INFO                   0x0002
#define  GLUT_CURSOR_DESTROY                0x0003
#define  GLUT_CURSOR_HELP                   0x0004
#define  GLUT_CURSOR_CYCLE                  0x0005
#define  GLUT_CURSOR_SPRAY                  0x0006
#define  GLUT_CURSOR_WAIT                   0x0007
#define  GLUT_CURSOR_TEXT                   0x0008
#define  GLUT_CURSOR_CROSSHAIR              0x0009
#define  GLUT_CURSOR_UP_DOWN                0x000A
#define  GLUT_CURSOR_LEFT_RIGHT             0x000B
#define  GLUT_CURSOR_TOP_SIDE               0x000C
#define  GLUT_CURSOR_BOTTOM_SIDE            0x000D
#define  GLUT_CURSOR_LEFT_SIDE              0x000E
#define  GLUT_CURSOR_RIGHT_SIDE             0x000F
#define  GLUT_CURSOR_TOP_LEFT_CORNER        0x0010
#define  GLUT_CURSOR_TOP_RIGHT_CORNER       0x0011
#define  GLUT_CURSOR_BOTTOM_RIGHT_CORNER    0x0012
#define  GLUT_CURSOR_BOTTOM_LEFT_CORNER     0x0013
#define  GLUT_CURSOR_INHERIT                0x0064
#define  GLUT_CURSOR_NONE                   0x0065
#define  GLUT_CURSOR_FULL_CROSSHAIR         0x0066

/* glutSetKeyRepeat. */
#define  GLUT_KEY_REPEAT_OFF                0x0000
#define  GLUT_KEY_REPEAT_ON                 0x0001
#define  GLUT_KEY_REPEAT_DEFAULT            0x0002

/* Initialisation (spec 2). glutInit takes -display, -geometry WxH+X+Y, -direct, -indirect,
 * -iconic, -gldebug and -sync out of argv, as freeglut does. */
GLAPI void GLAPIENTRY glutInit(int* pargc, char** argv);
GLAPI void GLAPIENTRY glutInitWindowPosition(int x, int y);
GLAPI void GLAPIENTRY glutInitWindowSize(int width, int height);
GLAPI void GLAPIENTRY glutInitDisplayMode(unsigned int displayMode);
GLAPI void GLAPIENTRY glutInitDisplayString(const char* displayMode);
GLAPI void GLAPIENTRY glutMainLoop(void);

/* Windows (spec 4): each its own glass context, made current with the window. */
GLAPI int GLAPIENTRY glutCreateWindow(const char* title);
GLAPI int GLAPIENTRY glutCreateSubWindow(int window, int x, int y, int width, int height);
GLAPI void GLAPIENTRY glutDestroyWindow(int window);
/* Game mode (GLUT 3.7): a window covering the screen from its corner, without a border. */
GLAPI void GLAPIENTRY glutGameModeString(const char* string);
GLAPI int GLAPIENTRY glutEnterGameMode(void);
GLAPI void GLAPIENTRY glutLeaveGameMode(void);
GLAPI int GLAPIENTRY glutGameModeGet(GLenum query);
GLAPI void GLAPIENTRY glutSetWindow(int window);
GLAPI int GLAPIENTRY glutGetWindow(void);
GLAPI void GLAPIENTRY glutSetWindowTitle(const char* title);
GLAPI void GLAPIENTRY glutSetIconTitle(const char* title);
GLAPI void GLAPIENTRY glutReshapeWindow(int width, int height);
GLAPI void GLAPIENTRY glutPositionWindow(int x, int y);
GLAPI void GLAPIENTRY glutShowWindow(void);
GLAPI void GLAPIENTRY glutHideWindow(void);
GLAPI void GLAPIENTRY glutIconifyWindow(void);
GLAPI void GLAPIENTRY glutPushWindow(void);
GLAPI void GLAPIENTRY glutPopWindow(void);
GLAPI void GLAPIENTRY glutFullScreen(void);
GLAPI void GLAPIENTRY glutPostWindowRedisplay(int window);
GLAPI void GLAPIENTRY glutPostRedisplay(void);
/* A double-buffered window shows its picture here; a single-buffered one on glFlush and
 * glFinish. */
GLAPI void GLAPIENTRY glutSwapBuffers(void);
GLAPI void GLAPIENTRY glutWarpPointer(int x, int y);
GLAPI void GLAPIENTRY glutSetCursor(int cursor);

/* Menus (spec 6): pop-ups drawn by glass over the window's picture, which they leave unchanged. */
GLAPI int GLAPIENTRY glutCreateMenu(void (*callback)(int menu));
GLAPI void GLAPIENTRY glutDestroyMenu(int menu);
GLAPI int GLAPIENTRY glutGetMenu(void);
GLAPI void GLAPIENTRY glutSetMenu(int menu);
GLAPI void GLAPIENTRY glutAddMenuEntry(const char* label, int value);
GLAPI void GLAPIENTRY glutAddSubMenu(const char* label, int subMenu);
GLAPI void GLAPIENTRY glutChangeToMenuEntry(int item, const char* label, int value);
GLAPI void GLAPIENTRY glutChangeToSubMenu(int item, const char* label, int value);
GLAPI void GLAPIENTRY glutRemoveMenuItem(int item);
GLAPI void GLAPIENTRY glutAttachMenu(int button);
GLAPI void GLAPIENTRY glutDetachMenu(int button);

/* Callbacks (spec 7). */
GLAPI void GLAPIENTRY glutTimerFunc(unsigned int time, void (*callback)(int), int value);
GLAPI void GLAPIENTRY glutIdleFunc(void (*callback)(void));
GLAPI void GLAPIENTRY glutKeyboardFunc(void (*callback)(unsigned char, int, int));
GLAPI void GLAPIENTRY glutSpecialFunc(void (*callback)(int, int, int));
GLAPI void GLAPIENTRY glutReshapeFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutVisibilityFunc(void (*callback)(int));
GLAPI void GLAPIENTRY glutDisplayFunc(void (*callback)(void));
GLAPI void GLAPIENTRY glutMouseFunc(void (*callback)(int, int, int, int));
GLAPI void GLAPIENTRY glutMotionFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutPassiveMotionFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutEntryFunc(void (*callback)(int));
GLAPI void GLAPIENTRY glutKeyboardUpFunc(void (*callback)(unsigned char, int, int));
GLAPI void GLAPIENTRY glutSpecialUpFunc(void (*callback)(int, int, int));
GLAPI void GLAPIENTRY glutMenuStateFunc(void (*callback)(int));
GLAPI void GLAPIENTRY glutMenuStatusFunc(void (*callback)(int, int, int));
GLAPI void GLAPIENTRY glutWindowStatusFunc(void (*callback)(int));
/* Devices glass knows none of (glutDeviceGet says so): their callbacks are kept and never called. */
GLAPI void GLAPIENTRY glutJoystickFunc(void (*callback)(unsigned int, int, int, int), int pollInterval);
GLAPI void GLAPIENTRY glutForceJoystickFunc(void);
GLAPI void GLAPIENTRY glutSpaceballMotionFunc(void (*callback)(int, int, int));
GLAPI void GLAPIENTRY glutSpaceballRotateFunc(void (*callback)(int, int, int));
GLAPI void GLAPIENTRY glutSpaceballButtonFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutButtonBoxFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutDialsFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutTabletMotionFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutTabletButtonFunc(void (*callback)(int, int, int, int));

/* Overlays, colour maps and video resizing, which glass's RGBA windows do not have: as freeglut,
 * glutLayerGet(GLUT_OVERLAY_POSSIBLE) is 0, the overlay calls do nothing (the overlay display
 * callback is kept and never called), glutGetColor gives -1 and glutVideoResizeGet 0. */
GLAPI void GLAPIENTRY glutEstablishOverlay(void);
GLAPI void GLAPIENTRY glutRemoveOverlay(void);
GLAPI void GLAPIENTRY glutUseLayer(GLenum layer);
GLAPI void GLAPIENTRY glutPostOverlayRedisplay(void);
GLAPI void GLAPIENTRY glutPostWindowOverlayRedisplay(int window);
GLAPI void GLAPIENTRY glutShowOverlay(void);
GLAPI void GLAPIENTRY glutHideOverlay(void);
GLAPI void GLAPIENTRY glutOverlayDisplayFunc(void (*callback)(void));
GLAPI void GLAPIENTRY glutSetColor(int color, GLfloat red, GLfloat green, GLfloat blue);
GLAPI GLfloat GLAPIENTRY glutGetColor(int color, int component);
GLAPI void GLAPIENTRY glutCopyColormap(int window);
GLAPI int GLAPIENTRY glutVideoResizeGet(GLenum query);
GLAPI void GLAPIENTRY glutSetupVideoResizing(void);
GLAPI void GLAPIENTRY glutStopVideoResizing(void);
GLAPI void GLAPIENTRY glutVideoResize(int x, int y, int width, int height);
GLAPI void GLAPIENTRY glutVideoPan(int x, int y, int width, int height);

/* State (spec 9). */
GLAPI int GLAPIENTRY glutGet(GLenum query);
GLAPI int GLAPIENTRY glutDeviceGet(GLenum query);
GLAPI int GLAPIENTRY glutGetModifiers(void);
GLAPI int GLAPIENTRY glutLayerGet(GLenum query);
GLAPI int GLAPIENTRY glutExtensionSupported(const char* extension);
GLAPI void GLAPIENTRY glutIgnoreKeyRepeat(int ignore);
GLAPI void GLAPIENTRY glutSetKeyRepeat(int repeatMode);
GLAPI void GLAPIENTRY glutReportErrors(void);

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
/* freeglut's teacup and teaspoon from the same teaset, tessellated as freeglut does, to the
 * teapot's scale for the same size: the cup upright on its saucer about the origin (y up, handle
 * towards -x), the spoon lying along the z axis, its bowl towards -z. */
GLAPI void GLAPIENTRY glutSolidTeacup(GLdouble size);
GLAPI void GLAPIENTRY glutWireTeacup(GLdouble size);
GLAPI void GLAPIENTRY glutSolidTeaspoon(GLdouble size);
GLAPI void GLAPIENTRY glutWireTeaspoon(GLdouble size);

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
