#include "osmesa/context_request.h"

#include <GL/osmesa.h>

#include <cstdio>

#include "core/gl_strings.h"
#include "osmesa/buffer_layout.h"

namespace glass::osmesa {
namespace {

// The version glass implements, from the start of GL_VERSION ("<major>.<minor> ...").
void implementedVersion(int& major, int& minor) {
  major = 1;
  minor = 0;
  std::sscanf(gl::glString(GL_VERSION), "%d.%d", &major, &minor);
}

}  // namespace

bool readContextRequest(const int* attributes, ContextRequest& request, std::string& error) {
  request = ContextRequest{};
  for (int i = 0; attributes && attributes[i] != 0; i += 2) {
    const int value = attributes[i + 1];
    switch (attributes[i]) {
      case OSMESA_FORMAT:
        if (!isBufferFormat(static_cast<GLenum>(value))) {
          error = "format " + std::to_string(value) +
                  " is not OSMESA_RGBA, _BGRA, _ARGB, _RGB, _BGR or _RGB_565";
          return false;
        }
        request.format = static_cast<GLenum>(value);
        break;
      case OSMESA_DEPTH_BITS:
      case OSMESA_STENCIL_BITS:
      case OSMESA_ACCUM_BITS:
        if (value < 0) {
          error = "negative buffer bits " + std::to_string(value);
          return false;
        }
        (attributes[i] == OSMESA_DEPTH_BITS     ? request.depthBits
         : attributes[i] == OSMESA_STENCIL_BITS ? request.stencilBits
                                                : request.accumBits) = value;
        break;
      case OSMESA_PROFILE:
        if (value == OSMESA_CORE_PROFILE) {
          error = "glass implements the compatibility profile only, not OSMESA_CORE_PROFILE";
          return false;
        }
        if (value != OSMESA_COMPAT_PROFILE) {
          error = "profile " + std::to_string(value) + " is not OSMESA_COMPAT_PROFILE";
          return false;
        }
        break;
      case OSMESA_CONTEXT_MAJOR_VERSION:
        request.majorVersion = value;
        break;
      case OSMESA_CONTEXT_MINOR_VERSION:
        request.minorVersion = value;
        break;
      default:
        error = "unknown attribute " + std::to_string(attributes[i]);
        return false;
    }
  }
  int major = 0, minor = 0;
  implementedVersion(major, minor);
  if (request.majorVersion < 1 || request.minorVersion < 0) {
    error = "version " + std::to_string(request.majorVersion) + "." +
            std::to_string(request.minorVersion) + " does not exist";
    return false;
  }
  if (request.majorVersion > major || (request.majorVersion == major && request.minorVersion > minor)) {
    error = "version " + std::to_string(request.majorVersion) + "." +
            std::to_string(request.minorVersion) + " asked for; glass implements OpenGL " +
            std::to_string(major) + "." + std::to_string(minor);
    return false;
  }
  return true;
}

}  // namespace glass::osmesa
