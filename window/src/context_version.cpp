// freeglut's context settings, glutGetProcAddress and glutGetModeValues (context_version.h).
#include "context_version.h"

#include <GL/freeglut.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstring>

#include "glut_errors.h"
#include "glut_state.h"

namespace glass::glut {

void requireContextGlassHas() {
  const State& s = state();
  if (s.contextMajor > 1 || (s.contextMajor == 1 && s.contextMinor > 4)) {
    fatalError("Unable to create OpenGL %d.%d context (flags %x, profile %x): glass provides "
               "OpenGL 1.4",
               s.contextMajor, s.contextMinor, static_cast<unsigned>(s.contextFlags),
               static_cast<unsigned>(s.contextProfile));
  }
}

namespace {

// One of glass's GLUT functions by name: a symbol this library defines.
GLUTproc ownGlutFunction(const char* name) {
  Dl_info self, found;
  if (!dladdr(reinterpret_cast<void*>(&glutGetProcAddress), &self)) return nullptr;
  void* symbol = dlsym(RTLD_DEFAULT, name);
  if (!symbol || !dladdr(symbol, &found) || found.dli_fbase != self.dli_fbase) return nullptr;
  return reinterpret_cast<GLUTproc>(symbol);
}

}  // namespace
}  // namespace glass::glut

using namespace glass::glut;

extern "C" {

void glutInitContextVersion(int majorVersion, int minorVersion) {
  state().contextMajor = majorVersion;
  state().contextMinor = minorVersion;
}
void glutInitContextFlags(int flags) { state().contextFlags = flags; }
void glutInitContextProfile(int profile) { state().contextProfile = profile; }

// As freeglut: GLUT's own functions, then the GL's (here glass's gl* entry points).
GLUTproc glutGetProcAddress(const char* procName) {
  requireInitialised("glutGetProcAddress");
  if (!procName) return nullptr;
  if (std::strncmp(procName, "glut", 4) == 0) return ownGlutFunction(procName);
  return reinterpret_cast<GLUTproc>(OSMesaGetProcAddress(procName));
}

int* glutGetModeValues(GLenum, int* size) {
  requireInitialised("glutGetModeValues");
  if (size) *size = 0;
  return nullptr;
}

}  // extern "C"
