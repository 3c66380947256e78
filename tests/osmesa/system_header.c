/* glass's <GL/osmesa.h> against Mesa's (Debian's libosmesa6-dev), compiled with -Werror by the
 * test osmesa.system_header:
 *  - every OSMESA_ name Mesa's header defines is defined by glass's (system_osmesa_names.h,
 *    written at configure time, has an #error for each missing one);
 *  - then Mesa's header is read after glass's: a function declared with another prototype is a
 *    conflicting declaration, and a macro defined with other tokens a redefinition, both errors
 *    here. So glass's names, values and prototypes are Mesa's. */
#include <GL/osmesa.h>

#include "system_osmesa_names.h"

/* glass's guard keeps Mesa's header out; lift it. */
#undef OSMESA_H
#include GLASS_SYSTEM_OSMESA_HEADER

int main(void) { return 0; }
