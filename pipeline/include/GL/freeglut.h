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

#ifdef __cplusplus
}
#endif

#endif /* GLASS_GL_FREEGLUT_H */
