#include "vertex/vertex_arrays.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "core/context.h"
#include "core/fast_paths.h"
#include "lists/command_recording.h"
#include "primitive/draw_pipeline.h"
#include "vertex/array_draw.h"
#include "vertex/array_fetch.h"
#include "vertex/attribute_conversion.h"
#include "vertex/immediate_mode.h"
#include "vertex/vertex_batch.h"

namespace glass::gl {

int arrayTypeBytes(GLenum type) {
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

int arrayElementStride(const ClientArray& a) {
  return a.stride != 0 ? a.stride : a.size * arrayTypeBytes(a.type);
}

namespace {

// Component i of an element as float: normalized by table 2.9 (colours, normals) or as a number.
float component(const unsigned char* element, GLenum type, int i, bool normalized) {
  switch (type) {
    case GL_BYTE: return arrayComponentToFloat(loadUnaligned<GLbyte>(element + i), normalized);
    case GL_UNSIGNED_BYTE: return arrayComponentToFloat(loadUnaligned<GLubyte>(element + i), normalized);
    case GL_SHORT: return arrayComponentToFloat(loadUnaligned<GLshort>(element + 2 * i), normalized);
    case GL_UNSIGNED_SHORT: return arrayComponentToFloat(loadUnaligned<GLushort>(element + 2 * i), normalized);
    case GL_INT: return arrayComponentToFloat(loadUnaligned<GLint>(element + 4 * i), normalized);
    case GL_UNSIGNED_INT: return arrayComponentToFloat(loadUnaligned<GLuint>(element + 4 * i), normalized);
    case GL_FLOAT: return loadUnaligned<GLfloat>(element + 4 * i);
    case GL_DOUBLE: return static_cast<float>(loadUnaligned<GLdouble>(element + 8 * i));
    default: return 0.0f;
  }
}

const unsigned char* elementAddress(const ClientArray& a, int index) {
  return static_cast<const unsigned char*>(a.pointer) +
         static_cast<long long>(index) * arrayElementStride(a);
}

// Reads `size` components and fills the rest from `defaults` (spec 2.8: missing coordinates
// default as for the corresponding immediate command).
void readArray(const ClientArray& a, int index, bool normalized, const float* defaults, int count,
               float* out) {
  const unsigned char* element = elementAddress(a, index);
  for (int i = 0; i < count; ++i) {
    out[i] = i < a.size ? component(element, a.type, i, normalized) : defaults[i];
  }
}

}  // namespace

ArrayElementLayout currentElementLayout(const ArrayState& arrays) {
  ArrayElementLayout layout;
  layout.edgeFlag = arrays.edgeFlag.enabled && arrays.edgeFlag.pointer;
  for (int u = 0; u < kTextureUnitCount; ++u)
    layout.texCoord[u] = arrays.texCoord[u].enabled && arrays.texCoord[u].pointer;
  layout.normal = arrays.normal.enabled && arrays.normal.pointer;
  layout.color = arrays.color.enabled && arrays.color.pointer;
  layout.vertex = arrays.vertex.enabled && arrays.vertex.pointer;
  layout.fogCoord = arrays.fogCoord.enabled && arrays.fogCoord.pointer;
  layout.secondaryColor = arrays.secondaryColor.enabled && arrays.secondaryColor.pointer;
  return layout;
}

namespace {

// The components an array without them gives (spec 2.8): as the immediate commands' defaults.
constexpr float kPointDefaults[4] = {0.0f, 0.0f, 0.0f, 1.0f};
constexpr float kColorDefaults[4] = {0.0f, 0.0f, 0.0f, 1.0f};

}  // namespace

void readElement(const ArrayState& arrays, const ArrayElementLayout& layout, int index,
                 ArrayElementValues& out) {
  if (layout.edgeFlag) out.edgeFlag = *elementAddress(arrays.edgeFlag, index) != 0;
  for (int u = 0; u < kTextureUnitCount; ++u) {
    if (layout.texCoord[u])
      readArray(arrays.texCoord[u], index, false, kPointDefaults, 4, out.texCoord[u]);
  }
  if (layout.normal) readArray(arrays.normal, index, true, kPointDefaults, 3, out.normal);
  if (layout.color) readArray(arrays.color, index, true, kColorDefaults, 4, out.color);
  if (layout.secondaryColor) {
    readArray(arrays.secondaryColor, index, true, kColorDefaults, 3, out.secondaryColor);
  }
  if (layout.fogCoord) readArray(arrays.fogCoord, index, false, kPointDefaults, 1, &out.fogCoord);
  if (layout.vertex) readArray(arrays.vertex, index, false, kPointDefaults, 4, out.vertex);
}

void applyElement(Context& ctx, const ArrayElementLayout& layout, const ArrayElementValues& v) {
  if (layout.edgeFlag) edgeFlagCommand(ctx, v.edgeFlag);
  for (int u = 0; u < kTextureUnitCount; ++u) {
    if (layout.texCoord[u]) texCoordCommand(ctx, u, v.texCoord[u]);
  }
  if (layout.normal) normalCommand(ctx, v.normal[0], v.normal[1], v.normal[2]);
  if (layout.color) colorCommand(ctx, v.color[0], v.color[1], v.color[2], v.color[3]);
  if (layout.secondaryColor) {
    secondaryColorCommand(ctx, v.secondaryColor[0], v.secondaryColor[1], v.secondaryColor[2]);
  }
  if (layout.fogCoord) fogCoordCommand(ctx, v.fogCoord);
  if (layout.vertex) vertexCommand(ctx, v.vertex[0], v.vertex[1], v.vertex[2], v.vertex[3]);
}

void arrayElement(Context& ctx, int index) {
  const ArrayElementLayout layout = currentElementLayout(ctx.arrays);
  ArrayElementValues values;
  readElement(ctx.arrays, layout, index, values);
  // Compiled with the values read now (spec 5.4); executed like the immediate commands.
  compileOrExecuteOn(ctx, [=](Context& c) { applyElement(c, layout, values); });
}

namespace {

// Whether the elements of a draw go through the batched vertex path (vertex_batch.h): with the
// fast paths on, when the elements issue vertices, and when no vertex is traced (a traced vertex
// goes the reference way, one vertex at a time: teaching/vertex_trace.h). Called after
// beginCommand, which prepares the draw.
bool batchesElements(Context& ctx, const ArrayElementLayout& layout) {
  return fastPathsEnabled() && layout.vertex && ctx.draw->vertexSetup().trace == nullptr;
}

// The components of the attributes a compiled draw stores, as readElement gives them.
constexpr int kVertexComponents = 4, kColorComponents = 4, kNormalComponents = 3;
constexpr int kTexCoordComponents = 4, kSecondaryColorComponents = 3;

// Room for draw.count elements of each attribute of draw.layout.
void reserveElements(CompiledArrayDraw& draw) {
  const ArrayElementLayout& layout = draw.layout;
  const auto reserve = [&draw](bool stored, std::vector<float>& values, int components) {
    if (stored) values.reserve(static_cast<size_t>(draw.count) * static_cast<size_t>(components));
  };
  reserve(layout.vertex, draw.vertex, kVertexComponents);
  reserve(layout.color, draw.color, kColorComponents);
  reserve(layout.normal, draw.normal, kNormalComponents);
  for (int u = 0; u < kTextureUnitCount; ++u) reserve(layout.texCoord[u], draw.texCoord[u], kTexCoordComponents);
  reserve(layout.fogCoord, draw.fogCoord, 1);
  reserve(layout.secondaryColor, draw.secondaryColor, kSecondaryColorComponents);
  if (layout.edgeFlag) draw.edgeFlag.reserve(static_cast<size_t>(draw.count));
}

// Appends the attributes of draw.layout from one element's values to the draw's packed arrays.
void storeElement(const ArrayElementValues& e, CompiledArrayDraw& draw) {
  const ArrayElementLayout& layout = draw.layout;
  const auto append = [](std::vector<float>& to, const float* values, int n) {
    to.insert(to.end(), values, values + n);
  };
  if (layout.vertex) append(draw.vertex, e.vertex, kVertexComponents);
  if (layout.color) append(draw.color, e.color, kColorComponents);
  if (layout.normal) append(draw.normal, e.normal, kNormalComponents);
  for (int u = 0; u < kTextureUnitCount; ++u)
    if (layout.texCoord[u]) append(draw.texCoord[u], e.texCoord[u], kTexCoordComponents);
  if (layout.fogCoord) draw.fogCoord.push_back(e.fogCoord);
  if (layout.secondaryColor) append(draw.secondaryColor, e.secondaryColor, kSecondaryColorComponents);
  if (layout.edgeFlag) draw.edgeFlag.push_back(e.edgeFlag ? 1 : 0);
}

// The attributes of draw.layout of elements [0, count) (element indices[i], or first + i when
// indices is null), appended to the draw's packed arrays: what storeElement appends for each
// element's readElement values, read a batch at a time by fetchArrayRows (the same conversions,
// the type and size of each array looked at once per batch rather than once per component).
void storeElements(const ArrayState& arrays, const int* indices, int first, int count,
                   CompiledArrayDraw& draw) {
  constexpr int kBatch = kVertexBatch;
  const auto store = [&](const ClientArray& array, bool normalized, const float* defaults, int components,
                         std::vector<float>& to) {
    float rows[4][kBatch];
    float* const pointers[4] = {rows[0], rows[1], rows[2], rows[3]};
    const size_t end = to.size();
    to.resize(end + static_cast<size_t>(count) * static_cast<size_t>(components));
    for (int start = 0; start < count; start += kBatch) {
      const int n = std::min(kBatch, count - start);
      fetchArrayRows(array, normalized, defaults, components, indices ? indices + start : nullptr, first + start,
                     n, pointers);
      float* out = to.data() + end + static_cast<size_t>(start) * static_cast<size_t>(components);
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < components; ++c) out[i * components + c] = rows[c][i];
    }
  };
  const ArrayElementLayout& layout = draw.layout;
  if (layout.vertex) store(arrays.vertex, false, kPointDefaults, kVertexComponents, draw.vertex);
  if (layout.color) store(arrays.color, true, kColorDefaults, kColorComponents, draw.color);
  if (layout.normal) store(arrays.normal, true, kPointDefaults, kNormalComponents, draw.normal);
  for (int u = 0; u < kTextureUnitCount; ++u)
    if (layout.texCoord[u]) store(arrays.texCoord[u], false, kPointDefaults, kTexCoordComponents, draw.texCoord[u]);
  if (layout.fogCoord) store(arrays.fogCoord, false, kPointDefaults, 1, draw.fogCoord);
  if (layout.secondaryColor)
    store(arrays.secondaryColor, true, kColorDefaults, kSecondaryColorComponents, draw.secondaryColor);
  if (layout.edgeFlag)
    for (int i = 0; i < count; ++i)
      draw.edgeFlag.push_back(*elementAddress(arrays.edgeFlag, indices ? indices[i] : first + i) != 0 ? 1 : 0);
}

// Client arrays over a compiled draw's packed values: each attribute tightly packed, GL_FLOAT
// components (the edge flags as bytes), so that readElement gives back exactly the stored values
// and the batched path can replay them. Attributes the layout does not read stay disabled.
ArrayState arraysOverStoredElements(const CompiledArrayDraw& draw) {
  const auto over = [](const std::vector<float>& values, int components) {
    return ClientArray{!values.empty(), components, GL_FLOAT, 0, values.data()};
  };
  ArrayState arrays;
  arrays.vertex = over(draw.vertex, kVertexComponents);
  arrays.color = over(draw.color, kColorComponents);
  arrays.normal = over(draw.normal, kNormalComponents);
  for (int u = 0; u < kTextureUnitCount; ++u) arrays.texCoord[u] = over(draw.texCoord[u], kTexCoordComponents);
  arrays.fogCoord = over(draw.fogCoord, 1);
  arrays.secondaryColor = over(draw.secondaryColor, kSecondaryColorComponents);
  arrays.edgeFlag = {!draw.edgeFlag.empty(), 1, GL_UNSIGNED_BYTE, 0, draw.edgeFlag.data()};
  return arrays;
}

// Replays a display list's array draw: the stored elements through the batched path, or one at
// a time, over arrays made of them (the context's own arrays are put back after).
void replayCompiledDraw(Context& ctx, const CompiledArrayDraw& draw) {
  beginCommand(ctx, draw.mode);
  if (!ctx.assembly.active) return;
  struct RestoredArrays {
    Context& ctx;
    ArrayState saved;
    ~RestoredArrays() { ctx.arrays = saved; }
  } restore{ctx, ctx.arrays};
  ctx.arrays = arraysOverStoredElements(draw);
  if (draw.count > 0 && batchesElements(ctx, draw.layout)) {
    drawArrayElementsBatched(ctx, draw.layout, nullptr, 0, draw.count);
  } else {
    ArrayElementValues values;
    for (int i = 0; i < draw.count; ++i) {
      readElement(ctx.arrays, draw.layout, i, values);
      applyElement(ctx, draw.layout, values);
    }
  }
  endCommand(ctx);
}

}  // namespace

void drawArrayElements(Context& ctx, GLenum mode, const int* indices, int first, int count) {
  const ArrayElementLayout layout = currentElementLayout(ctx.arrays);
  if (ctx.lists.isCompiling()) {
    auto draw = std::make_shared<CompiledArrayDraw>();
    draw->mode = mode;
    draw->layout = layout;
    draw->count = count;
    reserveElements(*draw);
    if (fastPathsEnabled()) {
      storeElements(ctx.arrays, indices, first, count, *draw);
    } else {
      ArrayElementValues values;
      for (int i = 0; i < count; ++i) {
        readElement(ctx.arrays, layout, indices ? indices[i] : first + i, values);
        storeElement(values, *draw);
      }
    }
    std::shared_ptr<const CompiledArrayDraw> compiled = std::move(draw);
    compileOrExecuteOn(ctx, [compiled](Context& c) { replayCompiledDraw(c, *compiled); });
    return;
  }
  beginCommand(ctx, mode);
  if (!ctx.assembly.active) return;
  // Indexed quads split along v1-v3, as Mesa's draw module splits indexed vertices
  // (primitive_assembly.cpp, drawQuads), on the batched path as on the reference path.
  if (indices != nullptr) ctx.assembly.pendingNeedsClipping = true;
  if (batchesElements(ctx, layout)) {
    drawArrayElementsBatched(ctx, layout, indices, first, count);
    endCommand(ctx);
    return;
  }
  ArrayElementValues values;
  for (int i = 0; i < count; ++i) {
    readElement(ctx.arrays, layout, indices ? indices[i] : first + i, values);
    applyElement(ctx, layout, values);
  }
  endCommand(ctx);
}

}  // namespace glass::gl
