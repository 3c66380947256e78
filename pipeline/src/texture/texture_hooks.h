// The interface between the pipeline and the texturing stage (spec 2.10.4, 2.11.4, 3.8). The
// pipeline calls these; the texturing stage implements them in texture/ (texture_hooks.cpp).
#pragma once

#include <GL/gl.h>

#include "glass/raster/fragment.h"

namespace glass::gl {

struct Context;
struct StateValue;

// glEnable/glDisable/glIsEnabled of GL_TEXTURE_1D/2D/..., GL_TEXTURE_GEN_S/T/R/Q of the active
// texture unit. Return false when cap is not a texturing capability.
bool setTextureCapability(Context& ctx, GLenum cap, bool enabled);
bool getTextureCapability(const Context& ctx, GLenum cap, bool& enabled);
// glGet of texturing state (GL_TEXTURE_BINDING_2D, ...). False when pname is not texturing state.
bool queryTextureState(const Context& ctx, GLenum pname, StateValue& value);

// Some texture target of some unit is enabled: the pipeline then computes texture coordinates
// per vertex, interpolates them, and calls applyTexturing per fragment.
bool texturingEnabled(const Context& ctx);
// One more than the highest texture unit with a target enabled (1 when only bump mapping is on):
// the units whose coordinates the vertex stage computes and the rasterizer interpolates.
int textureUnitsInUse(const Context& ctx);

// Per vertex: texture coordinate generation and the texture matrix of units 0 .. units - 1,
// giving (s, t, r, q) of unit u in varyings[varying::texCoordSlot(u) ..]. objectPosition is the
// vertex as given, eyePosition = modelview * objectPosition, eyeNormal as for lighting,
// vertexTexCoords[u] the vertex's glMultiTexCoord values of unit u.
void computeTexCoords(const Context& ctx, int units, const float (*vertexTexCoords)[4],
                      const float objectPosition[4], const float eyePosition[4],
                      const float eyeNormal[3], float* varyings);

// Per fragment, after rasterization: replaces color with the textured colour, each enabled unit
// in turn applying its environment to the previous unit's result (spec 3.8.13, 3.8.17). The
// fragment's texture coordinates of unit u are in its varyings from varying::texCoordSlot(u); the
// batch's attribute planes (triangles only) give the texture coordinates at the other pixels of
// the fragment's 2x2 quad, whose differences set the level of detail (texture_lod.h).
void applyTexturing(const Context& ctx, const raster::FragmentBatch& batch, int fragmentIndex,
                    float color[4]);

struct TextureObject;

// The lookup's minification and magnification differ, so it needs a level of detail.
bool needsLevelOfDetail(const TextureObject& texture);
// Lambda (spec 3.8.8) of `texture` at pixel (x, y) of a triangle with attribute planes `planes`,
// the unit's coordinates from varying `slot` and its bias `unitBias`: one value for the whole
// 2x2 quad of the pixel (texture_lod.h). Not for cube maps.
float quadLevelOfDetail(const Context& ctx, const TextureObject& texture, int slot, float unitBias,
                        const raster::AttributePlanes& planes, int x, int y);
// quadLevelOfDetail's last step, for a kernel that computes rho^2 (textureScaleFactorSquared of
// texture_lod.h) itself: lambda from rho^2 with the texture's GL_TEXTURE_MIN_LOD and
// GL_TEXTURE_MAX_LOD and the bias of the unit (unitBias) and the texture.
float textureLevelOfDetail(const TextureObject& texture, float unitBias, double rhoSquared);
// The bias textureLevelOfDetail adds: the unit's and the texture's, their sum clamped
// (OpenGL 1.4, 3.8.8).
float textureLodBias(const TextureObject& texture, float unitBias);
// For the fragment stage's fast kernels (fragment/block_kernels.h): when texturing is exactly one
// complete colour (not depth) 2D texture on unit 0 with a texture environment other than
// GL_COMBINE and no bump mapping, that texture; then applyTexturing amounts to sampleTexture (texture_sampler.h) at
// (s/q, t/q) with quadLevelOfDetail's lambda (or sampleTextureMagnified when the texture needs
// no level of detail), then applyTextureEnvironment with unit 0's environment. Null otherwise.
const TextureObject* singleTexture2D(const Context& ctx);

// GL_GLASS_bump_map (docs/texturing.md): bump mapping is on and its height map is a complete 2D
// texture. Only per-fragment lighting (GL_PHONG_WIN) uses it.
bool bumpMappingActive(const Context& ctx);

// Per fragment, before per-fragment lighting: perturbs the interpolated eye-space normal by the
// height map at the fragment's texture coordinates. Needs the batch's attribute planes (the
// derivatives of the eye position and texture coordinates); leaves the normal as it is without.
void perturbNormal(const Context& ctx, const raster::FragmentBatch& batch, int fragmentIndex,
                   float eyeNormal[3]);

}  // namespace glass::gl
