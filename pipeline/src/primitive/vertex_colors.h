// The colour selection stages of a primitive: two-sided lighting picks the back colours of
// back-facing polygons (spec 2.13.1), and flat shading gives every vertex the colours of the
// provoking vertex (spec 2.13.7). Both write the colour varyings (slots 0-7) of a primitive's own
// copy of its vertices.
#pragma once

#include "glass/raster/vertex.h"
#include "vertex/pipeline_vertex.h"
#include "vertex/varyings.h"

namespace glass::gl {

// Copies source's back colours over the front colour varyings of target.
inline void useBackColors(const PipelineVertex& source, raster::ClipVertex& target) {
  for (int i = 0; i < 4; ++i) {
    target.varyings[varying::kPrimaryColor + i] = source.backColor[i];
    target.varyings[varying::kSecondaryColor + i] = source.backSecondary[i];
  }
}

// Copies the provoking vertex's colours (front, or back when useBack) into target.
inline void useProvokingColors(const PipelineVertex& provoking, bool useBack,
                               raster::ClipVertex& target) {
  if (useBack) {
    useBackColors(provoking, target);
    return;
  }
  for (int i = 0; i < 8; ++i) target.varyings[i] = provoking.clip.varyings[i];
}

}  // namespace glass::gl
