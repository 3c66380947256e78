// Reading client arrays for many elements at once (the vertex fast path, vertex_batch.h): the
// type and size of an array are looked at once per call, not once per component as
// readElement does, and the values land one row per component, ready for loops over vertices.
// The conversions are readElement's (attribute_conversion.h), so the values are the same.
#pragma once

#include "vertex/vertex_arrays.h"

namespace glass::gl {

// For i in [0, count): element indices[i] (or first + i when indices is null) of array a, its
// components 0 .. components - 1 in rows[c][i]: normalized as table 2.9 says when `normalized`,
// and taken from defaults[c] past the array's size (spec 2.8).
void fetchArrayRows(const ClientArray& a, bool normalized, const float* defaults, int components,
                    const int* indices, int first, int count, float* const* rows);

}  // namespace glass::gl
