// Texture images (OpenGL 1.5 specification, sections 3.8.1 to 3.8.3 and 6.1.4): glTexImage1D/2D/3D,
// glTexSubImage1D/2D/3D, glCopyTexImage1D/2D, glCopyTexSubImage1D/2D/3D, glGetTexImage and
// glGetTexLevelParameter.
#include <GL/gl.h>

#include <vector>

#include "core/context.h"
#include "core/errors.h"
#include "lists/command_recording.h"
#include "primitive/queued_drawing.h"
#include "texture/texture_commands.h"

namespace glass::gl {
namespace {

// glTexImage executes at once with a proxy target (spec 5.4), otherwise it is compiled; a
// compiled command keeps the texels unpacked at compile time.
void submitTexImage(const TexImageArguments& args, const void* pixels) {
  Context* ctx = currentContext();
  if (ctx == nullptr) return;
  const bool proxy = args.target == GL_PROXY_TEXTURE_1D || args.target == GL_PROXY_TEXTURE_2D ||
                     args.target == GL_PROXY_TEXTURE_3D || args.target == GL_PROXY_TEXTURE_CUBE_MAP;
  if (proxy || !ctx->lists.isCompiling()) {
    texImage(*ctx, args, pixels, nullptr);
    return;
  }
  UnpackedTexels unpacked = unpackForDisplayList(*ctx, args, pixels);
  compileOrExecute([args, unpacked](Context& c) { texImage(c, args, nullptr, unpacked); });
}

void submitTexSubImage(const TexSubImageArguments& args, const void* pixels) {
  Context* ctx = currentContext();
  if (ctx == nullptr) return;
  if (!ctx->lists.isCompiling()) {
    texSubImage(*ctx, args, pixels, nullptr);
    return;
  }
  UnpackedTexels unpacked = unpackForDisplayList(*ctx, args, pixels);
  compileOrExecute([args, unpacked](Context& c) { texSubImage(c, args, nullptr, unpacked); });
}

// Table 6.1 (glGetTexImage): the components of a texel as R, G, B, A. Luminance and intensity
// come back in R, with G and B zero.
void texelToGetRGBA(BaseFormat base, const uint8_t* texel, float rgba[4]) {
  const float r = texel[0] / 255.0f, g = texel[1] / 255.0f, b = texel[2] / 255.0f, a = texel[3] / 255.0f;
  switch (base) {
    case BaseFormat::Alpha: rgba[0] = rgba[1] = rgba[2] = 0.0f; rgba[3] = a; break;
    case BaseFormat::Luminance:
    case BaseFormat::Intensity: rgba[0] = r; rgba[1] = rgba[2] = 0.0f; rgba[3] = 1.0f; break;
    case BaseFormat::LuminanceAlpha: rgba[0] = r; rgba[1] = rgba[2] = 0.0f; rgba[3] = a; break;
    case BaseFormat::RGB: rgba[0] = r; rgba[1] = g; rgba[2] = b; rgba[3] = 1.0f; break;
    case BaseFormat::RGBA: rgba[0] = r; rgba[1] = g; rgba[2] = b; rgba[3] = a; break;
  }
}

void getTexImage(Context& ctx, GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels) {
  if (rejectInsideBeginEnd(ctx)) return;
  // glGetTexImage reads a 1D or 2D texture or a cube map face; GL_TEXTURE_CUBE_MAP itself names
  // no image (spec 6.1.4).
  const ImageTarget named = imageTarget(ctx, target);
  if (named.texture == nullptr || target == GL_TEXTURE_CUBE_MAP)
    return recordError(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return recordError(ctx, GL_INVALID_VALUE);
  const bool depthData = format == GL_DEPTH_COMPONENT;
  if (GLenum e = depthData ? checkPixelFormatAndType(format, type) : checkTexelFormatAndType(format, type);
      e != GL_NO_ERROR)
    return recordError(ctx, e);
  const TextureImage& image = named.texture->image(named.face, level);
  // OpenGL 1.4, 6.1.4: depth images are read as GL_DEPTH_COMPONENT and only they are.
  if (image.defined() && depthData != image.isDepth()) return recordError(ctx, GL_INVALID_OPERATION);
  if (!image.defined() || pixels == nullptr) return;
  const PixelLayout layout = packLayout(ctx);
  if (depthData) {
    for (int j = 0; j < image.height; ++j)
      packDepthSpan(&image.depths[image.texelIndex(0, j, 0)], image.width, image.width, 0, j, type,
                    layout, pixels);
    return;
  }
  std::vector<float> row(static_cast<size_t>(image.width) * 4);
  // The slices of a 3D image follow each other GL_PACK_IMAGE_HEIGHT rows apart (or the image's
  // height when that is 0), after GL_PACK_SKIP_IMAGES slices (spec 6.1.4 and 3.8.1).
  const int imageRows = layout.imageHeight > 0 ? layout.imageHeight : image.height;
  for (int k = 0; k < image.depth; ++k) {
    PixelLayout sliceLayout = layout;
    if (target == GL_TEXTURE_3D)
      sliceLayout.skipRows = layout.skipRows + (layout.skipImages + k) * imageRows;
    for (int j = 0; j < image.height; ++j) {
      for (int i = 0; i < image.width; ++i)
        texelToGetRGBA(image.base, image.texel(i, j, k), &row[static_cast<size_t>(i) * 4]);
      packPixelRow(row.data(), image.width, j, format, type, sliceLayout, pixels);
    }
  }
}

// The image glGetTexLevelParameter describes: a level of the bound texture or of a proxy.
const TextureImage* levelImage(const Context& ctx, GLenum target, GLint level) {
  switch (target) {
    case GL_TEXTURE_1D: return &ctx.texture.unit().bound1D->levels[level];
    case GL_TEXTURE_2D: return &ctx.texture.unit().bound2D->levels[level];
    case GL_TEXTURE_3D: return &ctx.texture.unit().bound3D->levels[level];
    case GL_PROXY_TEXTURE_3D: return &ctx.texture.proxy3D[level];
    case GL_PROXY_TEXTURE_CUBE_MAP: return &ctx.texture.proxyCube[level];
    case GL_PROXY_TEXTURE_1D: return &ctx.texture.proxy1D[level];
    case GL_PROXY_TEXTURE_2D: return &ctx.texture.proxy2D[level];
    default: {
      const int face = cubeFaceOf(target);
      return face >= 0 ? &ctx.texture.unit().boundCube->image(face, level) : nullptr;
    }
  }
}

// Returns false (after recording the error) for a bad target, level or pname.
bool texLevelParameter(Context& ctx, GLenum target, GLint level, GLenum pname, double* value) {
  if (rejectInsideBeginEnd(ctx)) return false;
  if (levelImage(ctx, target, 0) == nullptr) {
    recordError(ctx, GL_INVALID_ENUM);
    return false;
  }
  if (level < 0 || level >= kMaxTextureLevels) {
    recordError(ctx, GL_INVALID_VALUE);
    return false;
  }
  const TextureImage& image = *levelImage(ctx, target, level);
  const bool defined = image.defined();
  const bool oneD = target == GL_TEXTURE_1D || target == GL_PROXY_TEXTURE_1D;
  const int rowBorder = oneD ? 0 : image.border;
  switch (pname) {
    // Widths and heights include the border (spec 6.1.3: TEXTURE_WIDTH is w_s).
    case GL_TEXTURE_WIDTH: *value = defined ? image.width + 2 * image.border : 0; return true;
    case GL_TEXTURE_HEIGHT: *value = defined ? image.height + 2 * rowBorder : 0; return true;
    case GL_TEXTURE_DEPTH: {
      const bool threeD = target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D;
      *value = defined ? image.depth + (threeD ? 2 * image.border : 0) : 0;
      return true;
    }
    case GL_TEXTURE_BORDER: *value = defined ? image.border : 0; return true;
    case GL_TEXTURE_INTERNAL_FORMAT: *value = defined ? image.internalFormat : (image.internalFormat == 0 ? 0 : 1); return true;
    case GL_TEXTURE_RED_SIZE:
    case GL_TEXTURE_GREEN_SIZE:
    case GL_TEXTURE_BLUE_SIZE:
    case GL_TEXTURE_ALPHA_SIZE:
    case GL_TEXTURE_LUMINANCE_SIZE:
    case GL_TEXTURE_INTENSITY_SIZE:
      *value = defined && !image.isDepth() ? componentBits(image.base, pname) : 0;
      return true;
    case GL_TEXTURE_DEPTH_SIZE: *value = defined ? image.depthBits : 0; return true;
    case GL_TEXTURE_COMPRESSED: *value = 0; return true;
    default: recordError(ctx, GL_INVALID_ENUM); return false;
  }
}

}  // namespace
}  // namespace glass::gl

using glass::gl::Context;

void GLAPIENTRY glTexImage1D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                             GLint border, GLenum format, GLenum type, const GLvoid* pixels) {
  glass::gl::submitTexImage({1, target, level, internalFormat, width, 1, 1, border, format, type},
                            pixels);
}

void GLAPIENTRY glTexImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                             GLsizei height, GLint border, GLenum format, GLenum type,
                             const GLvoid* pixels) {
  glass::gl::submitTexImage(
      {2, target, level, internalFormat, width, height, 1, border, format, type}, pixels);
}

void GLAPIENTRY glTexImage3D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                             GLsizei height, GLsizei depth, GLint border, GLenum format,
                             GLenum type, const GLvoid* pixels) {
  glass::gl::submitTexImage(
      {3, target, level, internalFormat, width, height, depth, border, format, type}, pixels);
}

void GLAPIENTRY glTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width,
                                GLenum format, GLenum type, const GLvoid* pixels) {
  glass::gl::submitTexSubImage({1, target, level, xoffset, 0, 0, width, 1, 1, format, type},
                               pixels);
}

void GLAPIENTRY glTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                GLsizei width, GLsizei height, GLenum format, GLenum type,
                                const GLvoid* pixels) {
  glass::gl::submitTexSubImage(
      {2, target, level, xoffset, yoffset, 0, width, height, 1, format, type}, pixels);
}

void GLAPIENTRY glTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                GLenum format, GLenum type, const GLvoid* pixels) {
  glass::gl::submitTexSubImage(
      {3, target, level, xoffset, yoffset, zoffset, width, height, depth, format, type}, pixels);
}

void GLAPIENTRY glCopyTexImage1D(GLenum target, GLint level, GLenum internalFormat, GLint x, GLint y,
                                 GLsizei width, GLint border) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::finishQueuedDrawing(ctx);
    glass::gl::copyTexImage(ctx, 1, target, level, internalFormat, x, y, width, 1, border);
  });
}

void GLAPIENTRY glCopyTexImage2D(GLenum target, GLint level, GLenum internalFormat, GLint x, GLint y,
                                 GLsizei width, GLsizei height, GLint border) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::finishQueuedDrawing(ctx);
    glass::gl::copyTexImage(ctx, 2, target, level, internalFormat, x, y, width, height, border);
  });
}

void GLAPIENTRY glCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                                    GLsizei width) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::finishQueuedDrawing(ctx);
    glass::gl::copyTexSubImage(ctx, 1, target, level, xoffset, 0, x, y, width, 1);
  });
}

void GLAPIENTRY glCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x,
                                    GLint y, GLsizei width, GLsizei height) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::finishQueuedDrawing(ctx);
    glass::gl::copyTexSubImage(ctx, 2, target, level, xoffset, yoffset, x, y, width, height);
  });
}

void GLAPIENTRY glCopyTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                    GLint zoffset, GLint x, GLint y, GLsizei width,
                                    GLsizei height) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::finishQueuedDrawing(ctx);  // the copy reads the framebuffer (queued_drawing.h)
    glass::gl::copyTexSubImage(ctx, 3, target, level, xoffset, yoffset, x, y, width, height,
                               zoffset);
  });
}

void GLAPIENTRY glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels) {
  glass::gl::executeNow([=](Context& ctx) { glass::gl::getTexImage(ctx, target, level, format, type, pixels); });
}

void GLAPIENTRY glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    double value;
    if (glass::gl::texLevelParameter(ctx, target, level, pname, &value)) *params = static_cast<GLint>(value);
  });
}

void GLAPIENTRY glGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* params) {
  glass::gl::executeNow([=](Context& ctx) {
    double value;
    if (glass::gl::texLevelParameter(ctx, target, level, pname, &value)) *params = static_cast<GLfloat>(value);
  });
}
