// The texturing stage as the pipeline sees it (texture_hooks.h): texture coordinates per vertex,
// the textured colour per fragment, and the enables and glGet values of texturing state.
// Texture unit 0's coordinates are also those of bump mapping.
#include "texture/texture_hooks.h"

#include <algorithm>

#include "core/context.h"
#include "core/state_value.h"
#include "texture/bump_mapping.h"
#include "texture/cube_map.h"
#include "texture/depth_comparison.h"
#include "texture/texture_combine.h"
#include "texture/texture_environment.h"
#include "texture/texture_lod.h"
#include "texture/texture_sampler.h"
#include "vertex/varyings.h"

namespace glass::gl {

bool setTextureCapability(Context& ctx, GLenum cap, bool enabled) {
  TextureUnit& u = ctx.texture.unit();
  switch (cap) {
    case GL_TEXTURE_1D: u.enabled1D = enabled; return true;
    case GL_TEXTURE_2D: u.enabled2D = enabled; return true;
    case GL_TEXTURE_3D: u.enabled3D = enabled; return true;
    case GL_TEXTURE_CUBE_MAP: u.enabledCube = enabled; return true;
    case GL_TEXTURE_GEN_S:
    case GL_TEXTURE_GEN_T:
    case GL_TEXTURE_GEN_R:
    case GL_TEXTURE_GEN_Q: u.texGen[cap - GL_TEXTURE_GEN_S].enabled = enabled; return true;
    case GL_BUMP_MAP_GLASS: ctx.texture.bumpMap.enabled = enabled; return true;
    default: return false;
  }
}

bool getTextureCapability(const Context& ctx, GLenum cap, bool& enabled) {
  const TextureUnit& u = ctx.texture.unit();
  switch (cap) {
    case GL_TEXTURE_1D: enabled = u.enabled1D; return true;
    case GL_TEXTURE_2D: enabled = u.enabled2D; return true;
    case GL_TEXTURE_3D: enabled = u.enabled3D; return true;
    case GL_TEXTURE_CUBE_MAP: enabled = u.enabledCube; return true;
    case GL_TEXTURE_GEN_S:
    case GL_TEXTURE_GEN_T:
    case GL_TEXTURE_GEN_R:
    case GL_TEXTURE_GEN_Q: enabled = u.texGen[cap - GL_TEXTURE_GEN_S].enabled; return true;
    case GL_BUMP_MAP_GLASS: enabled = ctx.texture.bumpMap.enabled; return true;
    default: return false;
  }
}

bool queryTextureState(const Context& ctx, GLenum pname, StateValue& value) {
  bool enabled = false;
  if (getTextureCapability(ctx, pname, enabled)) {
    value.setBooleans({enabled});
    return true;
  }
  const TextureUnit& u = ctx.texture.unit();
  switch (pname) {
    case GL_TEXTURE_BINDING_1D: value.setIntegers({double(u.bound1D->name)}); return true;
    case GL_TEXTURE_BINDING_2D: value.setIntegers({double(u.bound2D->name)}); return true;
    case GL_TEXTURE_BINDING_3D: value.setIntegers({double(u.bound3D->name)}); return true;
    case GL_TEXTURE_BINDING_CUBE_MAP: value.setIntegers({double(u.boundCube->name)}); return true;
    case GL_MAX_3D_TEXTURE_SIZE: value.setIntegers({double(kMax3DTextureSize)}); return true;
    case GL_MAX_TEXTURE_SIZE:
    case GL_MAX_CUBE_MAP_TEXTURE_SIZE: value.setIntegers({double(kMaxTextureSize)}); return true;
    case GL_MAX_TEXTURE_LOD_BIAS: value.setFloats(&kMaxTextureLodBias, 1); return true;
    default: return false;
  }
}

bool texturingEnabled(const Context& ctx) {
  return textureUnitsInUse(ctx) > 0;
}

int textureUnitsInUse(const Context& ctx) {
  const TextureState& t = ctx.texture;
  for (int u = kTextureUnitCount - 1; u >= 0; --u) {
    if (t.units[u].anyTargetEnabled()) return u + 1;
  }
  // Bump mapping reads unit 0's coordinates.
  return t.bumpMap.enabled ? 1 : 0;
}

namespace {

// One unit's (s, t, r, q): generation where enabled, else the vertex's coordinates, then the
// unit's texture matrix (spec 2.11.4: transformed as a column vector).
void unitTexCoords(const Context& ctx, int unit, const float vertexTexCoord[4],
                   const float objectPosition[4], const float eyePosition[4],
                   const float eyeNormal[3], float out[4]) {
  const TextureUnit& u = ctx.texture.units[unit];
  float coords[4];
  for (int i = 0; i < 4; ++i) coords[i] = vertexTexCoord[i];
  bool anyEyeVectors = false;
  for (const TexGenCoordinate& g : u.texGen)
    anyEyeVectors |= g.enabled && isEyeSpaceVectorMode(g.mode);
  EyeSpaceVectors vectors;
  if (anyEyeVectors) vectors = eyeSpaceVectors(eyePosition, eyeNormal);
  for (int i = 0; i < 4; ++i) {
    if (u.texGen[i].enabled)
      coords[i] = generateTexCoordinate(u.texGen[i], i, objectPosition, eyePosition, vectors);
  }
  transformVector4(ctx.transform.texture[unit].top(), coords, out);
}

}  // namespace

void computeTexCoords(const Context& ctx, int units, const float (*vertexTexCoords)[4],
                      const float objectPosition[4], const float eyePosition[4],
                      const float eyeNormal[3], float* varyings) {
  for (int u = 0; u < units; ++u) {
    unitTexCoords(ctx, u, vertexTexCoords[u], objectPosition, eyePosition, eyeNormal,
                  varyings + varying::texCoordSlot(u));
  }
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
  const std::shared_ptr<TextureObject> t = ctx.texture.names->find(b.texture);
  if (!t) return nullptr;
  return t->target == GL_TEXTURE_2D && t->complete ? t.get() : nullptr;
}

}  // namespace

namespace {

// A cube map's filtered texel (section 3.8.6): the face the fragment's (s, t, r) points at. For
// the level of detail, the directions at the quad's pixels are projected on that face, and their
// differences times the face size stand in for the derivatives of u and v.
void sampleCubeMap(const Context& ctx, const TextureObject& texture, int slot, float unitBias,
                   const raster::FragmentBatch& batch, const raster::Fragment& f, float texel[4]) {
  const float* tc = f.varyings + slot;
  const CubeFaceCoordinates c = cubeFaceCoordinates(tc[0], tc[1], tc[2]);
  if (!needsLevelOfDetail(texture) || batch.planes == nullptr) {
    sampleTextureMagnified(texture, c.s, c.t, texel, c.face);
    return;
  }
  const raster::AttributePlanes& planes = *batch.planes;
  const PixelQuad quad = pixelQuadOf(f.x, f.y, ctx.framebuffer.height());
  // The direction at a pixel centre: (s/w, t/w, r/w) from the planes; the positive 1/w does not
  // change the face projection.
  auto projected = [&](double x, double y, float* s, float* t) {
    float r[3];
    for (int k = 0; k < 3; ++k) {
      const int v = slot + k;
      r[k] = static_cast<float>(planes.a0[v] + planes.dx[v] * x + planes.dy[v] * y);
    }
    cubeFaceProjection(c.face, r[0], r[1], r[2], s, t);
  };
  const double left = quad.left + 0.5, top = quad.top + 0.5;
  float sUL, tUL, sUR, tUR, sLL, tLL;
  projected(left, top, &sUL, &tUL);
  projected(left + 1.0, top, &sUR, &tUR);
  projected(left, top - 1.0, &sLL, &tLL);
  TexCoordDerivatives d;
  d.dsdx = sUR - sUL;
  d.dtdx = tUR - tUL;
  d.dsdy = sUL - sLL;
  d.dtdy = tUL - tLL;
  const TextureImage& base = texture.baseImage();
  const double rhoSquared = textureScaleFactorSquared(d, base.width, base.height);
  sampleTexture(texture, c.s, c.t, textureLevelOfDetail(texture, unitBias, rhoSquared), texel, c.face);
}

// The filtered texel of `texture` for a fragment, with the texture coordinates in the fragment's
// varyings from `slot` and the level-of-detail bias `unitBias` of the unit (spec 3.8.8).
void sampleUnit(const Context& ctx, const TextureObject& texture, int slot, float unitBias,
                const raster::FragmentBatch& batch, const raster::Fragment& f, float texel[4]) {
  if (texture.target == GL_TEXTURE_CUBE_MAP)
    return sampleCubeMap(ctx, texture, slot, unitBias, batch, f, texel);
  const float* tc = f.varyings + slot;
  const float q = tc[3];
  const float s = tc[0] / q, t = tc[1] / q, r = tc[2] / q;
  if (!needsLevelOfDetail(texture) || batch.planes == nullptr) {
    // Points and lines carry no derivatives: the base level, magnified (spec 3.8.9).
    sampleTextureMagnified(texture, s, t, texel, 0, r);
    return;
  }
  const float lambda = quadLevelOfDetail(ctx, texture, slot, unitBias, *batch.planes, f.x, f.y);
  sampleTexture(texture, s, t, lambda, texel, 0, r);
}

}  // namespace

bool needsLevelOfDetail(const TextureObject& texture) {
  // Lambda only matters when the minification and magnification lookups differ.
  const SamplerParameters& p = texture.params;
  return isMipmapFilter(p.minFilter) || p.minFilter != p.magFilter;
}

float quadLevelOfDetail(const Context& ctx, const TextureObject& texture, int slot, float unitBias,
                        const raster::AttributePlanes& planes, int x, int y) {
  const bool threeD = texture.target == GL_TEXTURE_3D;
  const bool twoD = texture.target == GL_TEXTURE_2D || threeD;
  // One lambda per 2x2 pixel quad (texture_lod.h): every fragment of the quad computes the
  // same value from the same upper-left pixel.
  const PixelQuad quad = pixelQuadOf(x, y, ctx.framebuffer.height());
  const TexCoordDerivatives d =
      quadTexCoordDifferences(planes, slot, slot + 1, slot + 3, quad, twoD);
  const TextureImage& base = texture.baseImage();
  double rhoSquared = textureScaleFactorSquared(d, base.width, twoD ? base.height : 0);
  if (threeD) {
    // Equation 3.21 with the w terms: the differences of r/q, times the depth, join u's and v's.
    const TexCoordDerivatives dr =
        quadTexCoordDifferences(planes, slot + 2, slot + 1, slot + 3, quad, false);
    const double dwdx = dr.dsdx * base.depth, dwdy = dr.dsdy * base.depth;
    const double u2x = d.dsdx * base.width, v2x = d.dtdx * base.height;
    const double u2y = d.dsdy * base.width, v2y = d.dtdy * base.height;
    rhoSquared =
        std::max(u2x * u2x + v2x * v2x + dwdx * dwdx, u2y * u2y + v2y * v2y + dwdy * dwdy);
  }
  return textureLevelOfDetail(texture, unitBias, rhoSquared);
}

float textureLodBias(const TextureObject& texture, float unitBias) {
  return std::clamp(unitBias + texture.params.lodBias, -kMaxTextureLodBias, kMaxTextureLodBias);
}

float textureLevelOfDetail(const TextureObject& texture, float unitBias, double rhoSquared) {
  const SamplerParameters& p = texture.params;
  return levelOfDetailFromSquaredScale(rhoSquared, p.minLod, p.maxLod, textureLodBias(texture, unitBias));
}

const TextureObject* singleTexture2D(const Context& ctx) {
  if (textureUnitsInUse(ctx) != 1 || ctx.texture.bumpMap.enabled) return nullptr;
  const TextureUnit& unit = ctx.texture.units[0];
  const TextureObject* texture = unit.activeTexture();
  if (texture == nullptr || texture->target != GL_TEXTURE_2D || unit.env.mode == GL_COMBINE)
    return nullptr;
  // A depth texture's texel is a depth or the result of a comparison with r, and its environment
  // uses GL_DEPTH_TEXTURE_MODE's base format (texture/depth_comparison.h): the reference path.
  if (texture->baseImage().isDepth()) return nullptr;
  return texture;
}

void applyTexturing(const Context& ctx, const raster::FragmentBatch& batch, int fragmentIndex,
                    float color[4]) {
  const raster::Fragment& f = batch.fragments[fragmentIndex];
  const TextureState& state = ctx.texture;
  // First every unit's texel, since GL_COMBINE may read any unit's (the GL 1.4 crossbar).
  float texels[kTextureUnitCount][4];
  const float* unitTexels[kTextureUnitCount] = {};
  const TextureObject* textures[kTextureUnitCount] = {};
  bool any = false;
  for (int u = 0; u < kTextureUnitCount; ++u) {
    const TextureUnit& unit = state.units[u];
    if (!unit.anyTargetEnabled()) continue;
    textures[u] = unit.activeTexture();
    if (textures[u] == nullptr) continue;
    sampleUnit(ctx, *textures[u], varying::texCoordSlot(u), unit.env.lodBias, batch, f, texels[u]);
    unitTexels[u] = texels[u];
    any = true;
  }
  if (!any) return;
  // Then the environments in order of the units, each on the previous unit's result; a unit
  // that is off passes its input on (spec 3.8.17).
  const float primary[4] = {color[0], color[1], color[2], color[3]};
  for (int u = 0; u < kTextureUnitCount; ++u) {
    if (textures[u] == nullptr) continue;
    const TextureEnvironment& env = state.units[u].env;
    if (env.mode == GL_COMBINE) {
      CombineSources sources;
      sources.texel = texels[u];
      sources.unitTexels = unitTexels;
      sources.primary = primary;
      sources.previous = color;
      applyCombine(env, sources, color);
    } else {
      applyTextureEnvironment(env.mode, environmentBaseFormat(*textures[u]), texels[u], env.color,
                              color);
    }
  }
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
