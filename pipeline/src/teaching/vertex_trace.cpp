#include "teaching/vertex_trace.h"

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "core/context.h"
#include "lighting/lighting_equation.h"
#include "primitive/viewport_transform.h"
#include "teaching/per_context_table.h"
#include "vertex/varyings.h"
#include "vertex/vertex_stage.h"

namespace glass::gl {
namespace {

PerContextTable<VertexTrace>& traces() {
  static PerContextTable<VertexTrace> table;
  return table;
}

// A whole non-negative number running from text up to the end or to `stop`.
bool parseCount(const char* text, char stop, long& value, const char** end) {
  char* after = nullptr;
  if (*text < '0' || *text > '9') return false;
  value = std::strtol(text, &after, 10);
  if (after == text || (*after != '\0' && *after != stop) || value < 0) return false;
  *end = after;
  return true;
}

std::string format4(const float v[4]) {
  char text[128];
  std::snprintf(text, sizeof text, "(%11.6f, %11.6f, %11.6f, %11.6f)", static_cast<double>(v[0]),
                static_cast<double>(v[1]), static_cast<double>(v[2]), static_cast<double>(v[3]));
  return text;
}

std::string format3(double x, double y, double z) {
  char text[128];
  std::snprintf(text, sizeof text, "(%11.6f, %11.6f, %11.6f)", x, y, z);
  return text;
}
std::string format3(const float v[3]) { return format3(v[0], v[1], v[2]); }

// Which clip planes the vertex lies outside (spec 2.12): a primitive using it is cut there, or
// removed when all its vertices lie outside one plane.
std::string clipping(const raster::ClipVertex& v, unsigned userPlanes) {
  const float x = v.clip[0], y = v.clip[1], z = v.clip[2], w = v.clip[3];
  std::string outside;
  auto add = [&](bool out, const std::string& plane) {
    if (out) outside += (outside.empty() ? "" : ", ") + plane;
  };
  add(x < -w, "left (x < -w)");
  add(x > w, "right (x > w)");
  add(y < -w, "bottom (y < -w)");
  add(y > w, "top (y > w)");
  add(z < -w, "near (z < -w)");
  add(z > w, "far (z > w)");
  for (int i = 0; i < raster::kMaxUserClipPlanes; ++i) {
    add((userPlanes >> i & 1u) && v.userClipDistance[i] < 0.0f, "user clip plane " + std::to_string(i));
  }
  if (outside.empty()) return "          inside the view volume: clipping leaves it as it is\n";
  return "          outside " + outside + ": clipping cuts its primitives there, or removes those wholly outside\n";
}

// The lighting equation (spec 2.13.1) term by term, as the pipeline evaluates it.
std::string lightingTerms(const Context& ctx, int material, const float eye[4], const float normal[3],
                          const char* face) {
  const LightingState& l = ctx.lighting;
  float point[3], primary[4], secondary[4];
  eyePointFromHomogeneous(eye, point);
  LightingTerms terms;
  evaluateLighting(l, l.materials[material], point, normal, primary, secondary, &terms);
  std::string text = std::string("  lighting, ") + face +
                     " (spec 2.13.1: c = e + a_m a_scene + sum att spot (a_m a_l + (n.L) d_m d_l + f (n.h)^s s_m s_l))\n";
  text += "    e + a_m a_scene     " + format3(terms.base) + "\n";
  for (int i = 0; i < terms.lightCount; ++i) {
    const LightingTerms::Light& t = terms.lights[i];
    char heading[200];
    std::snprintf(heading, sizeof heading,
                  "    light %d: att %.6f, spot %.6f, n.L %.6f, f (n.h)^s %.6f\n", t.index,
                  static_cast<double>(t.attenuation), static_cast<double>(t.spot), static_cast<double>(t.nDotL),
                  static_cast<double>(t.specularFactor));
    text += heading;
    text += "      ambient           " + format3(t.ambient) + "\n";
    text += "      diffuse           " + format3(t.diffuse) + "\n";
    text += "      specular          " + format3(t.specular) + "\n";
  }
  text += "    colour              " + format4(primary) + "   the sum, clamped; alpha is d_m's\n";
  if (l.model.separateSpecular) text += "    secondary           " + format4(secondary) + "   the specular sum (GL_SEPARATE_SPECULAR_COLOR)\n";
  return text;
}

}  // namespace

void attachVertexTraceFromEnvironment(Context& ctx) {
  const char* value = std::getenv("GLASS_TRACE_VERTEX");
  if (!value || !*value) return;
  auto trace = std::make_unique<VertexTrace>();
  const char* end = nullptr;
  bool ok = parseCount(value, '@', trace->vertex, &end);
  if (ok && *end == '@') ok = parseCount(end + 1, '\0', trace->frame, &end);
  if (!ok) {
    std::fprintf(stderr, "glass: GLASS_TRACE_VERTEX=%s is not N or N@FRAME (whole numbers from 0); no trace\n", value);
    return;
  }
  traces().attach(ctx, std::move(trace));
}

void detachVertexTrace(const Context& ctx) { traces().detach(ctx); }

VertexTrace* vertexTraceFor(const Context& ctx) {
  VertexTrace* trace = traces().find(ctx);
  return trace && !trace->done ? trace : nullptr;
}

void traceVertex(const Context& ctx, const VertexStageSetup& s, VertexTrace& trace, const float object[4],
                 const float eye[4], const float normal[3], const PipelineVertex& out) {
  const long index = trace.verticesSeen++;
  if (trace.done || trace.framesEnded != trace.frame || index != trace.vertex) return;
  trace.done = true;

  char heading[96];
  std::snprintf(heading, sizeof heading, "glass trace: vertex %ld of frame %ld\n", trace.vertex, trace.frame);
  std::string text = heading;
  const raster::ClipVertex& v = out.clip;
  text += "  object  " + format4(object) + "   as given\n";
  text += "  eye     " + format4(eye) + "   = MODELVIEW x object\n";
  text += "  clip    " + format4(v.clip) + "   = PROJECTION x eye\n";
  raster::WindowVertex window;
  const ViewportTransform viewport =
      makeViewportTransform(ctx.transform.viewport, ctx.transform.depthNear, ctx.transform.depthFar);
  if (toWindow(viewport, v, 0, window)) {
    const double w = v.clip[3];
    text += "  ndc     " + format3(v.clip[0] / w, v.clip[1] / w, v.clip[2] / w) + "                = clip xyz / clip w\n";
    text += "  window  " + format3(window.x, window.y, window.z) +
            "                = viewport and depth range applied (pixels, y up from the bottom row)\n";
  } else {
    text += "  ndc     none: clip w is 0 or the division overflows (clipping decides what is drawn)\n";
  }
  text += clipping(v, s.clipPlaneMask);

  const char* normalHow = s.normalize ? ", normalized (GL_NORMALIZE)" : s.rescaleNormal ? ", rescaled (GL_RESCALE_NORMAL)" : "";
  text += "  normal  " + format3(ctx.current.normal) + "                as given\n";
  text += "          " + format3(normal) + "                eye space = normal x MODELVIEW^-1 (spec 2.11.3)" + normalHow + "\n";

  const float* colour = v.varyings + varying::kPrimaryColor;
  if (s.lightPerVertex) {
    text += lightingTerms(ctx, kFrontMaterial, eye, normal, "front face");
    if (s.twoSided) {
      const float reversed[3] = {-normal[0], -normal[1], -normal[2]};
      text += lightingTerms(ctx, kBackMaterial, eye, reversed, "back face, normal reversed (two-sided)");
    }
    text += "  colour  " + format4(colour) + "   lit per vertex, front face\n";
  } else if (s.phong) {
    text += "  colour  " + format4(colour) + "   the current colour: GL_PHONG_WIN lights each fragment\n";
  } else {
    text += "  colour  " + format4(ctx.current.color) + "   as given; lighting off\n";
    text += "          " + format4(colour) + "   clamped to [0, 1] (spec 2.14.6)\n";
  }
  for (int u = 0; u < s.textureUnits; ++u) {
    text += "  texture unit " + std::to_string(u) + "\n";
    text += "    as given            " + format4(ctx.current.texCoord[u]) + "\n";
    text += "    after texgen and the texture matrix " + format4(v.varyings + varying::texCoordSlot(u)) + "\n";
  }
  trace.report = text;
  std::fputs(text.c_str(), stderr);
}

std::string vertexTraceReport(const Context& ctx) {
  const VertexTrace* trace = traces().find(ctx);
  return trace ? trace->report : std::string();
}

void endTracedFrame(Context& ctx) {
  VertexTrace* trace = traces().find(ctx);
  if (trace == nullptr) return;
  if (!trace->done && trace->framesEnded == trace->frame) {
    trace->done = true;
    char text[200];
    std::snprintf(text, sizeof text, "glass trace: vertex %ld of frame %ld was not reached: the frame had %ld vertices\n",
                  trace->vertex, trace->frame, trace->verticesSeen);
    trace->report = text;
    std::fputs(text, stderr);
  }
  ++trace->framesEnded;
  trace->verticesSeen = 0;
}

}  // namespace glass::gl
