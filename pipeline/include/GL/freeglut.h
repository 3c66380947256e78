/* glass: <GL/freeglut.h>, for programs written for freeglut: <GL/glut.h> (GLUT 3.7, and the
 * freeglut additions to the shapes and fonts), and freeglut's additions to the window API with
 * freeglut 3's names and values (freeglut_ext.h). */
#ifndef GLASS_GL_FREEGLUT_H
#define GLASS_GL_FREEGLUT_H

#include <stdarg.h>

#include <GL/glut.h>

#ifdef __cplusplus
extern "C" {
#endif

/* More special keys. */
#define GLUT_KEY_NUM_LOCK           0x006D
#define GLUT_KEY_BEGIN              0x006E
#define GLUT_KEY_DELETE             0x006F
#define GLUT_KEY_SHIFT_L            0x0070
#define GLUT_KEY_SHIFT_R            0x0071
#define GLUT_KEY_CTRL_L             0x0072
#define GLUT_KEY_CTRL_R             0x0073
#define GLUT_KEY_ALT_L              0x0074
#define GLUT_KEY_ALT_R              0x0075
#define GLUT_KEY_SUPER_L            0x0076
#define GLUT_KEY_SUPER_R            0x0077
#define GLUT_ACTIVE_SUPER           0x0008

/* What closing a window from the window manager does (glutSetOption with
 * GLUT_ACTION_ON_WINDOW_CLOSE): exit the program (the default), return from glutMainLoop, or
 * close that window alone and go on. */
#define GLUT_ACTION_EXIT                         0
#define GLUT_ACTION_GLUTMAINLOOP_RETURNS         1
#define GLUT_ACTION_CONTINUE_EXECUTION           2

#define GLUT_CREATE_NEW_CONTEXT                  0
#define GLUT_USE_CURRENT_CONTEXT                 1
#define GLUT_FORCE_INDIRECT_CONTEXT              0
#define GLUT_ALLOW_DIRECT_CONTEXT                1
#define GLUT_TRY_DIRECT_CONTEXT                  2
#define GLUT_FORCE_DIRECT_CONTEXT                3

/* More glutGet queries and glutSetOption options. */
#define  GLUT_INIT_STATE                    0x007C
#define  GLUT_ACTION_ON_WINDOW_CLOSE        0x01F9
#define  GLUT_WINDOW_BORDER_WIDTH           0x01FA
#define  GLUT_WINDOW_BORDER_HEIGHT          0x01FB
#define  GLUT_WINDOW_HEADER_HEIGHT          0x01FB
#define  GLUT_VERSION                       0x01FC
#define  GLUT_RENDERING_CONTEXT             0x01FD
#define  GLUT_DIRECT_RENDERING              0x01FE
#define  GLUT_FULL_SCREEN                   0x01FF
#define  GLUT_SKIP_STALE_MOTION_EVENTS      0x0204

/* The event loop: one pass over the pending events, timers and redisplays; leaving
 * glutMainLoop; and freeing everything GLUT made, windows and menus. */
GLAPI void GLAPIENTRY glutMainLoopEvent(void);
GLAPI void GLAPIENTRY glutLeaveMainLoop(void);
GLAPI void GLAPIENTRY glutExit(void);

GLAPI void GLAPIENTRY glutFullScreenToggle(void);
GLAPI void GLAPIENTRY glutLeaveFullScreen(void);

/* Callbacks: the mouse wheel (wheel 0, direction +1 away from the user, -1 towards; without it
 * the wheel is buttons 3 and 4 of glutMouseFunc), window moves, and closing (both names are
 * the same callback, as in freeglut). */
GLAPI void GLAPIENTRY glutMouseWheelFunc(void (*callback)(int, int, int, int));
GLAPI void GLAPIENTRY glutPositionFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutCloseFunc(void (*callback)(void));
GLAPI void GLAPIENTRY glutWMCloseFunc(void (*callback)(void));
GLAPI void GLAPIENTRY glutMenuDestroyFunc(void (*callback)(void));

GLAPI void GLAPIENTRY glutSetOption(GLenum option_flag, int value);
GLAPI void* GLAPIENTRY glutGetWindowData(void);
GLAPI void GLAPIENTRY glutSetWindowData(void* data);
GLAPI void* GLAPIENTRY glutGetMenuData(void);
GLAPI void GLAPIENTRY glutSetMenuData(void* data);

/* Error and warning handlers, called instead of printing (an error still ends the program when
 * the handler returns). */
GLAPI void GLAPIENTRY glutInitErrorFunc(void (*callback)(const char* fmt, va_list ap));
GLAPI void GLAPIENTRY glutInitWarningFunc(void (*callback)(const char* fmt, va_list ap));

/* The OpenGL version, flags and profile a new window's context is to have. glass is OpenGL 1.4:
 * asking for more, a core profile or a forward-compatible context makes glutCreateWindow fail
 * with freeglut's message. glutGet tells what was asked. */
#define  GLUT_INIT_MAJOR_VERSION            0x0200
#define  GLUT_INIT_MINOR_VERSION            0x0201
#define  GLUT_INIT_FLAGS                    0x0202
#define  GLUT_INIT_PROFILE                  0x0203
#define  GLUT_DEBUG                         0x0001
#define  GLUT_FORWARD_COMPATIBLE            0x0002
#define  GLUT_CORE_PROFILE                  0x0001
#define  GLUT_COMPATIBILITY_PROFILE         0x0002
GLAPI void GLAPIENTRY glutInitContextVersion(int majorVersion, int minorVersion);
GLAPI void GLAPIENTRY glutInitContextFlags(int flags);
GLAPI void GLAPIENTRY glutInitContextProfile(int profile);

/* A GL or GLUT function of glass by name (NULL for others). */
typedef void (*GLUTproc)();
GLAPI GLUTproc GLAPIENTRY glutGetProcAddress(const char* procName);

/* The values glass's windows can have for a display mode bit (glutGetModeValues with
 * GLUT_AUX or GLUT_MULTISAMPLE): none, since they have no aux buffers or multisampling. */
GLAPI int* GLAPIENTRY glutGetModeValues(GLenum mode, int* size);

/* The font of a menu's entries: one of the GLUT_BITMAP_* fonts. */
GLAPI void GLAPIENTRY glutSetMenuFont(int menuID, void* font);

/* Multi-pointer input, mobile applications' pause and resume, and contexts made again, which
 * glass's desktop windows do not have: the callbacks are kept and never called. */
#define GLUT_APPSTATUS_PAUSE                0x0001
#define GLUT_APPSTATUS_RESUME               0x0002
GLAPI void GLAPIENTRY glutMultiEntryFunc(void (*callback)(int, int));
GLAPI void GLAPIENTRY glutMultiButtonFunc(void (*callback)(int, int, int, int, int));
GLAPI void GLAPIENTRY glutMultiMotionFunc(void (*callback)(int, int, int));
GLAPI void GLAPIENTRY glutMultiPassiveFunc(void (*callback)(int, int, int));
GLAPI void GLAPIENTRY glutInitContextFunc(void (*callback)(void));
GLAPI void GLAPIENTRY glutAppStatusFunc(void (*callback)(int));

/* Shader attributes for the shapes of OpenGL 3 core contexts; glass's shapes are drawn with the
 * fixed-function arrays, so these have no effect. */
GLAPI void GLAPIENTRY glutSetVertexAttribCoord3(GLint attrib);
GLAPI void GLAPIENTRY glutSetVertexAttribNormal(GLint attrib);
GLAPI void GLAPIENTRY glutSetVertexAttribTexCoord2(GLint attrib);

#ifdef __cplusplus
}
#endif

#endif /* GLASS_GL_FREEGLUT_H */
