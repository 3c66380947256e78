/* freeglut's shapes (glutSolidSphere, glutWireCube, ...) for the Mesa builds of the GL programs.
 *
 * freeglut 3 draws its shapes through plain GL vertex arrays and needs no window for that, but
 * each shape function first checks that glutInit ran, and without an X display glutInit cannot.
 * The check reports through freeglut's error handler, which by default prints and exits; with a
 * handler installed (glutInitErrorFunc, a freeglut 3 extension) it returns and the shape is drawn
 * into the current (OSMesa) context. This constructor installs a handler that drops the
 * "called without first calling 'glutInit'" complaint before main() runs, so the same program
 * source draws freeglut's shapes under Mesa and glass's under glass. */
#include <GL/freeglut.h>

#include <stdarg.h>

static void ignoreFreeglutMessage(const char *format, va_list arguments)
{
  (void)format;
  (void)arguments;
}

__attribute__((constructor)) static void installFreeglutErrorHandler(void)
{
  glutInitErrorFunc(ignoreFreeglutMessage);
  glutInitWarningFunc(ignoreFreeglutMessage);
}
