// The interface between the pipeline and the texturing stage (spec 2.10.4, 2.11.4, 3.8). The
// pipeline calls these; the texturing stage implements them in texture/ (texture_hooks.cpp).
#pragma once

#include <GL/gl.h>

#include "glass/raster/fragment.h"

namespace glass::gl {

struct Context;
struct StateValue;

// glEnable/glDisable/glIsEnabled of GL_TEXTURE_1D/2D/..., GL_TEXTURE_GEN_S/T/R/Q. Return false
// when cap is not a texturing capability.
bool setTextureCapability(Context& ctx, GLenum cap, bool enabled);
bool getTextureCapability(const Context& ctx, GLenum cap, bool& enabled);
// glGet of texturing state (GL_TEXTURE_BINDING_2D, ...). False when pname is not texturing state.
bool queryTextureState(const Context& ctx, GLenum pname, StateValue& value);

// Some texture target is enabled: the pipeline then computes texture coordinates per vertex,
// interpolates them, and calls applyTexturing per fragment.
bool texturingEnabled(const Context& ctx);

// Per vertex: texture coordinate generation and the texture matrix, giving (s, t, r, q).
// objectPosition is the vertex as given, eyePosition = modelview * objectPosition, eyeNormal as
// for lighting. The current texture coordinate is ctx.current.texCoord.
void computeTexCoords(const Context& ctx, const float objectPosition[4], const float eyePosition[4],
                      const float eyeNormal[3], float out[4]);

// Per fragment, after rasterization: replaces color with the textured colour (spec 3.8.13).
// The fragment's texture coordinates are batch.fragments[fragmentIndex].varyings[9..12]; the
// batch's attribute planes (triangles only) give the texture coordinates at the other pixels of
// the fragment's 2x2 quad, whose differences set the level of detail (texture_lod.h).
void applyTexturing(const Context& ctx, const raster::FragmentBatch& batch, int fragmentIndex,
                    float color[4]);

// GL_GLASS_bump_map (docs/texturing.md): bump mapping is on and its height map is a complete 2D
// texture. Only per-fragment lighting (GL_PHONG_WIN) uses it.
bool bumpMappingActive(const Context& ctx);

// Per fragment, before per-fragment lighting: perturbs the interpolated eye-space normal by the
// height map at the fragment's texture coordinates. Needs the batch's attribute planes (the
// derivatives of the eye position and texture coordinates); leaves the normal as it is without.
void perturbNormal(const Context& ctx, const raster::FragmentBatch& batch, int fragmentIndex,
                   float eyeNormal[3]);

}  // namespace glass::gl
