// The texturing stage as the pipeline sees it (texture_hooks.h): texture coordinates per vertex,
// the textured colour per fragment, and the enables and glGet values of texturing state.
#include "texture/texture_hooks.h"

#include "core/context.h"
#include "core/state_value.h"
#include "texture/bump_mapping.h"
#include "texture/texture_environment.h"
#include "texture/texture_lod.h"
#include "texture/texture_sampler.h"
#include "vertex/varyings.h"

namespace glass::gl {

bool setTextureCapability(Context& ctx, GLenum cap, bool enabled) {
  TextureState& t = ctx.texture;
  switch (cap) {
    case GL_TEXTURE_1D: t.enabled1D = enabled; return true;
    case GL_TEXTURE_2D: t.enabled2D = enabled; return true;
    case GL_TEXTURE_GEN_S:
    case GL_TEXTURE_GEN_T:
    case GL_TEXTURE_GEN_R:
    case GL_TEXTURE_GEN_Q: t.texGen[cap - GL_TEXTURE_GEN_S].enabled = enabled; return true;
    case GL_BUMP_MAP_GLASS: t.bumpMap.enabled = enabled; return true;
    default: return false;
  }
}

bool getTextureCapability(const Context& ctx, GLenum cap, bool& enabled) {
  const TextureState& t = ctx.texture;
  switch (cap) {
    case GL_TEXTURE_1D: enabled = t.enabled1D; return true;
    case GL_TEXTURE_2D: enabled = t.enabled2D; return true;
    case GL_TEXTURE_GEN_S:
    case GL_TEXTURE_GEN_T:
    case GL_TEXTURE_GEN_R:
    case GL_TEXTURE_GEN_Q: enabled = t.texGen[cap - GL_TEXTURE_GEN_S].enabled; return true;
    case GL_BUMP_MAP_GLASS: enabled = t.bumpMap.enabled; return true;
    default: return false;
  }
}

bool queryTextureState(const Context& ctx, GLenum pname, StateValue& value) {
  bool enabled = false;
  if (getTextureCapability(ctx, pname, enabled)) {
    value.setBooleans({enabled});
    return true;
  }
  const TextureState& t = ctx.texture;
  switch (pname) {
    case GL_TEXTURE_BINDING_1D: value.setIntegers({static_cast<double>(t.bound1D->name)}); return true;
    case GL_TEXTURE_BINDING_2D: value.setIntegers({static_cast<double>(t.bound2D->name)}); return true;
    case GL_MAX_TEXTURE_SIZE: value.setIntegers({static_cast<double>(kMaxTextureSize)}); return true;
    case GL_MAX_TEXTURE_UNITS: value.setIntegers({1}); return true;
    default: return false;
  }
}

bool texturingEnabled(const Context& ctx) {
  const TextureState& t = ctx.texture;
  return t.enabled1D || t.enabled2D || t.bumpMap.enabled;
}

void computeTexCoords(const Context& ctx, const float objectPosition[4], const float eyePosition[4],
                      const float eyeNormal[3], float out[4]) {
  const TextureState& t = ctx.texture;
  float coords[4];
  for (int i = 0; i < 4; ++i) coords[i] = ctx.current.texCoord[i];
  bool anySphereMap = false;
  for (const TexGenCoordinate& g : t.texGen) anySphereMap |= g.enabled && g.mode == GL_SPHERE_MAP;
  float sphereMap[2] = {0.0f, 0.0f};
  if (anySphereMap) sphereMapCoordinates(eyePosition, eyeNormal, &sphereMap[0], &sphereMap[1]);
  for (int i = 0; i < 4; ++i) {
    if (t.texGen[i].enabled)
      coords[i] = generateTexCoordinate(t.texGen[i], i, objectPosition, eyePosition, sphereMap);
  }
  // Spec 2.11.4 ends with the texture matrix: (s, t, r, q) is transformed as a column vector.
  transformVector4(ctx.transform.texture.top(), coords, out);
}

namespace {

// The screen-space derivatives of s/q and t/q at a fragment of a triangle, exactly (bump
// mapping needs the surface's tangents at the fragment itself). The
// rasterizer's planes give s/w, t/w and q/w as affine functions A, C, B of window (x, y); the 1/w
// cancels in the projected coordinate, s/q = A / B, so
//   d(s/q)/dx = (A_x B - A B_x) / B^2,
// and likewise for y and for t/q = C / B.
TexCoordDerivatives texCoordDerivatives(const raster::FragmentBatch& batch, const raster::Fragment& f,
                                        bool withT) {
  const raster::AttributePlanes& planes = *batch.planes;
  const double x = f.x + 0.5, y = f.y + 0.5;  // the pixel centre
  const int s = varying::kTexCoord, t = varying::kTexCoord + 1, q = varying::kTexCoord + 3;
  const double a = planes.a0[s] + planes.dx[s] * x + planes.dy[s] * y;
  const double b = planes.a0[q] + planes.dx[q] * x + planes.dy[q] * y;
  const double inverseB2 = 1.0 / (b * b);
  TexCoordDerivatives d;
  d.dsdx = (planes.dx[s] * b - a * planes.dx[q]) * inverseB2;
  d.dsdy = (planes.dy[s] * b - a * planes.dy[q]) * inverseB2;
  if (withT) {
    const double c = planes.a0[t] + planes.dx[t] * x + planes.dy[t] * y;
    d.dtdx = (planes.dx[t] * b - c * planes.dx[q]) * inverseB2;
    d.dtdy = (planes.dy[t] * b - c * planes.dy[q]) * inverseB2;
  }
  return d;
}

// The height map of GL_GLASS_bump_map when it can be sampled: a complete 2D texture object.
const TextureObject* bumpHeightMap(const Context& ctx) {
  const BumpMapState& b = ctx.texture.bumpMap;
  if (!b.enabled || b.texture == 0) return nullptr;
  const auto it = ctx.texture.objects.find(b.texture);
  if (it == ctx.texture.objects.end()) return nullptr;
  const TextureObject* t = it->second.get();
  return t->target == GL_TEXTURE_2D && t->complete ? t : nullptr;
}

}  // namespace

void applyTexturing(const Context& ctx, const raster::FragmentBatch& batch, int fragmentIndex,
                    float color[4]) {
  const TextureObject* texture = ctx.texture.activeTexture();
  if (texture == nullptr) return;
  const raster::Fragment& f = batch.fragments[fragmentIndex];
  const float* tc = f.varyings + varying::kTexCoord;
  const float q = tc[3];
  const float s = tc[0] / q, t = tc[1] / q;
  const bool twoD = texture->target == GL_TEXTURE_2D;

  float texel[4];
  const SamplerParameters& p = texture->params;
  // Lambda only matters when the minification and magnification lookups differ.
  const bool needLambda = isMipmapFilter(p.minFilter) || p.minFilter != p.magFilter;
  if (!needLambda || batch.planes == nullptr) {
    // Points and lines carry no derivatives: the base level, magnified (spec 3.8.9).
    sampleTextureMagnified(*texture, s, t, texel);
  } else {
    // One lambda per 2x2 pixel quad (texture_lod.h): every fragment of the quad computes the
    // same value from the same upper-left pixel.
    const PixelQuad quad = pixelQuadOf(f.x, f.y, ctx.framebuffer.height());
    const TexCoordDerivatives d =
        quadTexCoordDifferences(*batch.planes, varying::kTexCoord, varying::kTexCoord + 1,
                                varying::kTexCoord + 3, quad, twoD);
    const TextureImage& base = texture->baseImage();
    const double rhoSquared = textureScaleFactorSquared(d, base.width, twoD ? base.height : 0);
    const float lambda = levelOfDetailFromSquaredScale(rhoSquared, p.minLod, p.maxLod);
    sampleTexture(*texture, s, t, lambda, texel);
  }
  applyTextureEnvironment(ctx.texture.envMode, texture->baseImage().base, texel,
                          ctx.texture.envColor, color);
}

bool bumpMappingActive(const Context& ctx) { return bumpHeightMap(ctx) != nullptr; }

void perturbNormal(const Context& ctx, const raster::FragmentBatch& batch, int fragmentIndex,
                   float eyeNormal[3]) {
  const TextureObject* heightMap = bumpHeightMap(ctx);
  if (heightMap == nullptr || batch.planes == nullptr) return;
  const raster::Fragment& f = batch.fragments[fragmentIndex];
  const float* tc = f.varyings + varying::kTexCoord;
  const TexCoordDerivatives st = texCoordDerivatives(batch, f, true);
  double dPdx[3], dPdy[3];
  for (int k = 0; k < 3; ++k)
    batch.planes->derivatives(varying::kEyePosition + k, f.x, f.y, dPdx[k], dPdy[k]);
  perturbNormalByHeightMap(*heightMap, ctx.texture.bumpMap.scale, tc[0] / tc[3], tc[1] / tc[3], st,
                           dPdx, dPdy, eyeNormal);
}

}  // namespace glass::gl
