// The Utah teapot: Martin Newell's 1975 model as the public data set of 32 bicubic Bezier patches
// over 306 control points (with the bottom that was added to the original body later).
//
// The data is z-up, in Newell's units: the body stands on z = 0, its widest circle has radius 2,
// the lid knob reaches z = 3.15, the spout tip x = 3.525 and the handle x = -3. Patch p has the
// control points teapotControlPoints()[teapotPatchIndices()[p][4 i + j]] for i, j = 0..3, i along u.
#pragma once

#include "glass/geometry/bezier_surface.h"

#include <glm/vec3.hpp>

#include <array>
#include <span>
#include <vector>

namespace glass::geometry {

inline constexpr int kTeapotControlPointCount = 306;
inline constexpr int kTeapotPatchCount = 32;

enum class TeapotPart { Rim, Body, Handle, Spout, Lid, Bottom };

std::span<const glm::dvec3> teapotControlPoints();
// Zero-based indices into teapotControlPoints(), sixteen per patch, row by row.
std::span<const std::array<int, 16>> teapotPatchIndices();
// Patches 0-3 rim, 4-11 body, 12-15 handle, 16-19 spout, 20-27 lid, 28-31 bottom.
TeapotPart teapotPartOf(int patch);
// The 32 patches as integral bicubic BezierSurfaces.
std::vector<BezierSurface> teapotPatches();

}  // namespace glass::geometry
