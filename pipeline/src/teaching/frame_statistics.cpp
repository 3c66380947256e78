#include "teaching/frame_statistics.h"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string_view>

#include "core/context.h"
#include "teaching/per_context_table.h"
#include "teaching/texture_lookup.h"
#include "texture/texture_state.h"

namespace glass::gl {
namespace {

PerContextTable<FrameStatistics>& statisticsTable() {
  static PerContextTable<FrameStatistics> table;
  return table;
}

void restart(FrameStatistics& s) {
  // A query that spans frames keeps what this one gave it (frame_statistics.h).
  if (s.queryActive) {
    const PipelineCounts frame = pipelineCountsOf(s);
    for (int i = 0; i < kPipelineCountKinds; ++i) {
      s.queryGathered.values[i] += frame.values[i] - s.queryFrameStart.values[i];
    }
    s.queryFrameStart = PipelineCounts{};
  }
  s.vertices = s.points = s.lines = s.triangles = 0;
  s.culled = s.clippedAway = s.clipped = s.producedByClipping = 0;
  for (std::atomic<std::uint64_t>* count : {&s.fragments, &s.scissorRejected, &s.alphaRejected, &s.stencilRejected,
                                            &s.depthRejected, &s.passed, &s.texelReads}) {
    count->store(0, std::memory_order_relaxed);
  }
}

std::string line(const char* name, std::uint64_t value, const char* explanation = "") {
  char text[160];
  std::snprintf(text, sizeof text, "  %-22s %12llu%s%s\n", name, static_cast<unsigned long long>(value),
                *explanation ? "   " : "", explanation);
  return text;
}

}  // namespace

void addFragmentTally(FrameStatistics& s, int fragments, const FragmentTally& t) {
  constexpr auto relaxed = std::memory_order_relaxed;
  s.fragments.fetch_add(static_cast<std::uint64_t>(fragments), relaxed);
  s.scissorRejected.fetch_add(t.scissorRejected, relaxed);
  s.alphaRejected.fetch_add(t.alphaRejected, relaxed);
  s.stencilRejected.fetch_add(t.stencilRejected, relaxed);
  s.depthRejected.fetch_add(t.depthRejected, relaxed);
  s.passed.fetch_add(t.passed, relaxed);
  s.texelReads.fetch_add(t.texelReads, relaxed);
}

void attachFrameStatisticsFromEnvironment(Context& ctx) {
  const char* value = std::getenv("GLASS_STATS");
  if (!value || !*value || std::string_view(value) == "0") return;
  statisticsTable().attach(ctx, std::make_unique<FrameStatistics>()).printsFrames = true;
}

PipelineCounts pipelineCountsOf(const FrameStatistics& s) {
  PipelineCounts counts;
  counts.values = {s.vertices,
                   s.points,
                   s.lines,
                   s.triangles,
                   s.culled,
                   s.clippedAway,
                   s.clipped,
                   s.producedByClipping,
                   s.fragments.load(),
                   s.scissorRejected.load(),
                   s.alphaRejected.load(),
                   s.stencilRejected.load(),
                   s.depthRejected.load(),
                   s.passed.load(),
                   s.texelReads.load()};
  return counts;
}

void beginQueryCounting(Context& ctx) {
  FrameStatistics* s = frameStatisticsFor(ctx);
  if (s == nullptr) s = &statisticsTable().attach(ctx, std::make_unique<FrameStatistics>());
  s->queryActive = true;
  s->queryGathered = PipelineCounts{};
  s->queryFrameStart = pipelineCountsOf(*s);
}

PipelineCounts endQueryCounting(Context& ctx) {
  FrameStatistics* s = frameStatisticsFor(ctx);
  if (s == nullptr) return PipelineCounts{};
  PipelineCounts counts = s->queryGathered;
  const PipelineCounts now = pipelineCountsOf(*s);
  for (int i = 0; i < kPipelineCountKinds; ++i) counts.values[i] += now.values[i] - s->queryFrameStart.values[i];
  s->queryActive = false;
  // No cost once no query is active: the draws find no statistics again.
  if (!s->printsFrames) statisticsTable().detach(ctx);
  return counts;
}

void detachFrameStatistics(const Context& ctx) { statisticsTable().detach(ctx); }

FrameStatistics* frameStatisticsFor(const Context& ctx) { return statisticsTable().find(ctx); }

std::string formatFrameStatistics(const FrameStatistics& s) {
  const std::uint64_t primitives = s.points + s.lines + s.triangles;
  char heading[96];
  std::snprintf(heading, sizeof heading, "glass stats, frame %llu:\n", static_cast<unsigned long long>(s.frame));
  char kinds[96];
  std::snprintf(kinds, sizeof kinds, "(%llu points, %llu lines, %llu triangles)",
                static_cast<unsigned long long>(s.points), static_cast<unsigned long long>(s.lines),
                static_cast<unsigned long long>(s.triangles));
  std::string text = heading;
  text += line("vertices", s.vertices);
  text += line("primitives", primitives, kinds);
  text += line("culled", s.culled, "(back or front faces, glCullFace)");
  text += line("clipped away", s.clippedAway, "(wholly outside the view volume or a clip plane)");
  text += line("clipped", s.clipped, "(cut by clipping)");
  text += line("made by clipping", s.producedByClipping, "(the primitives the cut ones became)");
  text += line("fragments", s.fragments.load(), "(reaching the fragment stage)");
  text += line("scissor test failed", s.scissorRejected.load());
  text += line("alpha test failed", s.alphaRejected.load());
  text += line("stencil test failed", s.stencilRejected.load());
  text += line("depth test failed", s.depthRejected.load());
  text += line("passed every test", s.passed.load(), "(blended or written, under the masks)");
  text += line("texel reads", s.texelReads.load());
  return text;
}

void reportFrameStatistics(Context& ctx) {
  FrameStatistics* s = frameStatisticsFor(ctx);
  if (s == nullptr || !s->printsFrames) return;
  const bool drew = s->vertices != 0 || s->fragments.load() != 0;
  if (!drew) return;
  std::fputs(formatFrameStatistics(*s).c_str(), stderr);
  ++s->frame;
  restart(*s);
}

std::uint64_t texelReadsOf(const Context& ctx, const raster::FragmentBatch& batch, int index) {
  std::uint64_t reads = 0;
  for (int u = 0; u < kTextureUnitCount; ++u) {
    const TextureUnit& unit = ctx.texture.units[u];
    if (!unit.anyTargetEnabled()) continue;
    const TextureObject* texture = unit.activeTexture();
    if (texture == nullptr) continue;
    const TextureLookup lookup = textureLookupOf(ctx, *texture, u, batch, index);
    reads += static_cast<std::uint64_t>(lookup.levelsRead) * static_cast<std::uint64_t>(lookup.texelsPerLevel);
  }
  return reads;
}

}  // namespace glass::gl
