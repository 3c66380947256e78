// OSMesaGetProcAddress: the GL entry points and OSMesa functions of this library by name.
//
// The answer is the library's own dynamic symbol table, so it names exactly the entry points
// glass exports (every gl* function of <GL/gl.h>), with no list to keep in step. Other names
// (GLU's glu*, GLUT's glut*, glass's own glass*, anything another library defines) give NULL, as
// in Mesa, where GLU and GLUT are other libraries.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstring>

namespace {

bool isGLName(const char* name) {
  // gl followed by a capital: glBegin, glTexImage2D; not glu*, glut* or glass*.
  return std::strncmp(name, "gl", 2) == 0 && name[2] >= 'A' && name[2] <= 'Z';
}

bool isOSMesaName(const char* name) { return std::strncmp(name, "OSMesa", 6) == 0; }

}  // namespace

extern "C" OSMESAproc OSMesaGetProcAddress(const char* funcName) {
  if (!funcName || !(isGLName(funcName) || isOSMesaName(funcName))) return nullptr;
  Dl_info self;
  if (!dladdr(reinterpret_cast<void*>(&OSMesaGetProcAddress), &self)) return nullptr;
  // This library, already loaded: RTLD_NOLOAD only finds it.
  void* library = dlopen(self.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
  if (!library) return nullptr;
  void* symbol = dlsym(library, funcName);
  dlclose(library);
  // dlsym also searches the libraries this one needs; only this library's symbols count.
  Dl_info found;
  if (!symbol || !dladdr(symbol, &found) || found.dli_fbase != self.dli_fbase) return nullptr;
  return reinterpret_cast<OSMESAproc>(symbol);
}
