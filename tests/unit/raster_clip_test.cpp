// Clipping in homogeneous clip space: frustum planes, user planes, w = 0, attribute interpolation.
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "glass/raster/clip.h"
#include "raster_test_support.h"

using namespace glass::raster;
using glass::raster::test::clipVertex;

namespace {

// A varying that is a linear function of the clip coordinates stays that function after
// clipping, because clipping interpolates every attribute with the same t as the position.
float linearOf(const ClipVertex& v) { return 0.25f * v.clip[0] - 2.0f * v.clip[1] + 0.5f * v.clip[2] + 3.0f * v.clip[3]; }

ClipVertex withVarying(ClipVertex v) {
  v.varyings[0] = linearOf(v);
  return v;
}

bool insideFrustum(const ClipVertex& v, float tolerance) {
  const float w = v.clip[3];
  for (int i = 0; i < 3; ++i)
    if (v.clip[i] < -w - tolerance || v.clip[i] > w + tolerance) return false;
  return true;
}

ClipSettings withVaryings(int count) {
  ClipSettings s;
  s.varyingCount = count;
  return s;
}

}  // namespace

TEST_CASE("clip: a polygon inside every plane comes out unchanged") {
  const ClipVertex in[3] = {clipVertex(-0.5f, -0.5f, 0, 1), clipVertex(0.5f, -0.5f, 0, 1), clipVertex(0, 0.5f, 0.2f, 1)};
  ClipVertex out[kMaxClippedPolygonVertices + 3];
  REQUIRE(clipPolygon(in, 3, withVaryings(0), out) == 3);
  for (int i = 0; i < 3; ++i) CHECK(std::memcmp(&in[i], &out[i], sizeof(ClipVertex)) == 0);
  CHECK(outcode(in[0], ClipSettings{}) == 0u);
  CHECK(pointInside(in[2], ClipSettings{}));
}

TEST_CASE("clip: a polygon outside one plane disappears") {
  const ClipVertex in[3] = {clipVertex(2, 0, 0, 1), clipVertex(3, 1, 0, 1), clipVertex(2.5f, -1, 0, 1)};
  ClipVertex out[kMaxClippedPolygonVertices + 3];
  CHECK(clipPolygon(in, 3, withVaryings(0), out) == 0);
  CHECK(outcode(in[0], ClipSettings{}) == 2u);  // outside x <= w only
  CHECK_FALSE(pointInside(in[0], ClipSettings{}));
  // Outside different planes each, but not all outside one: the corner of the frustum survives.
  const ClipVertex corner[3] = {clipVertex(2, -0.5f, 0, 1), clipVertex(-0.5f, 2, 0, 1), clipVertex(3, 3, 0, 1)};
  CHECK(clipPolygon(corner, 3, withVaryings(0), out) >= 3);
}

TEST_CASE("clip: a triangle crossing the near plane is cut there, attributes interpolated") {
  const ClipVertex in[3] = {withVarying(clipVertex(-0.5f, -0.5f, -3.0f, 1.0f)),
                            withVarying(clipVertex(0.5f, -0.5f, 0.5f, 1.0f)),
                            withVarying(clipVertex(0.0f, 0.5f, 0.5f, 1.0f))};
  ClipVertex out[kMaxClippedPolygonVertices + 3];
  const int n = clipPolygon(in, 3, withVaryings(1), out);
  REQUIRE(n == 4);
  int onNear = 0;
  for (int i = 0; i < n; ++i) {
    CHECK(insideFrustum(out[i], 1e-6f));
    CHECK(out[i].varyings[0] == doctest::Approx(linearOf(out[i])).epsilon(1e-5));
    if (out[i].clip[2] == -out[i].clip[3]) ++onNear;
  }
  CHECK(onNear == 2);  // the two new vertices lie exactly on z = -w
  // Orientation is kept: the projected polygon turns the same way as the input.
  auto area = [](const ClipVertex* v, int count) {
    double a = 0;
    for (int i = 0; i < count; ++i) {
      const ClipVertex &p = v[i], &q = v[(i + 1) % count];
      a += double(p.clip[0]) / p.clip[3] * q.clip[1] / q.clip[3] - double(q.clip[0]) / q.clip[3] * p.clip[1] / p.clip[3];
    }
    return a;
  };
  CHECK(area(in, 3) > 0);
  CHECK(area(out, n) > 0);
}

TEST_CASE("clip: a triangle with a vertex behind the eye (crossing w = 0) comes out right") {
  // A perspective-style triangle: two vertices in front, one behind the eye (w < 0). Without
  // clipping before the division, the vertex behind would project to the wrong side.
  const ClipVertex in[3] = {withVarying(clipVertex(-0.5f, -0.2f, 0.5f, 1.0f)),
                            withVarying(clipVertex(0.5f, -0.2f, 0.5f, 1.0f)),
                            withVarying(clipVertex(0.3f, 0.4f, -1.5f, -1.0f))};
  ClipVertex out[kMaxClippedPolygonVertices + 3];
  const int n = clipPolygon(in, 3, withVaryings(1), out);
  REQUIRE(n >= 3);
  for (int i = 0; i < n; ++i) {
    CHECK(out[i].clip[3] > 0.0f);
    CHECK(insideFrustum(out[i], 1e-6f));
    CHECK(out[i].varyings[0] == doctest::Approx(linearOf(out[i])).epsilon(1e-5));
  }
  // The same with the lines: the segment from a front vertex to the one behind is cut at the
  // near plane and keeps its front end.
  ClipVertex a = in[0], b = in[2];
  REQUIRE(clipLine(a, b, withVaryings(1)));
  CHECK(std::memcmp(&a, &in[0], sizeof(ClipVertex)) == 0);
  CHECK(b.clip[3] > 0.0f);
  CHECK(b.clip[2] == doctest::Approx(-b.clip[3]).epsilon(1e-6));
  CHECK(b.varyings[0] == doctest::Approx(linearOf(b)).epsilon(1e-5));
  // A triangle entirely behind the eye is rejected.
  const ClipVertex behind[3] = {clipVertex(0, 0, 0.5f, -1), clipVertex(0.2f, 0, 0.5f, -1), clipVertex(0, 0.2f, 0.5f, -1)};
  CHECK(clipPolygon(behind, 3, withVaryings(0), out) == 0);
}

TEST_CASE("clip: user clip planes cut by the interpolated distance, only when enabled") {
  ClipVertex in[3] = {withVarying(clipVertex(-0.5f, -0.5f, 0, 1)), withVarying(clipVertex(0.5f, -0.5f, 0, 1)),
                      withVarying(clipVertex(0, 0.5f, 0, 1))};
  // Plane 3: keep y >= 0 (distance = y).
  for (ClipVertex& v : in) v.userClipDistance[3] = v.clip[1];
  ClipVertex out[kMaxClippedPolygonVertices + 3];
  CHECK(clipPolygon(in, 3, withVaryings(1), out) == 3);  // not enabled: untouched
  ClipSettings settings = withVaryings(1);
  settings.userPlaneMask = 1u << 3;
  CHECK(outcode(in[0], settings) == (1u << (6 + 3)));
  const int n = clipPolygon(in, 3, settings, out);
  REQUIRE(n == 3);
  for (int i = 0; i < n; ++i) {
    CHECK(out[i].clip[1] >= -1e-6f);
    CHECK(out[i].userClipDistance[3] >= 0.0f);
    CHECK(out[i].userClipDistance[3] == doctest::Approx(out[i].clip[1]).epsilon(1e-6));
    CHECK(out[i].varyings[0] == doctest::Approx(linearOf(out[i])).epsilon(1e-5));
  }
  // The cut vertices are at y = 0: (-0.25, 0) and (0.25, 0).
  int onPlane = 0;
  for (int i = 0; i < n; ++i)
    if (std::fabs(out[i].clip[1]) < 1e-6f) {
      CHECK(std::fabs(out[i].clip[0]) == doctest::Approx(0.25f));
      ++onPlane;
    }
  CHECK(onPlane == 2);
  // Lines and points honour the plane too.
  ClipVertex a = in[0], b = in[2];
  REQUIRE(clipLine(a, b, settings));
  CHECK(a.clip[1] == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK_FALSE(pointInside(in[0], settings));
  CHECK(pointInside(in[2], settings));
}

TEST_CASE("clip: triangles sharing an edge get bit-identical cut points") {
  // The edge p-q crosses x = w; one triangle walks it p->q, the other q->p.
  const ClipVertex p = clipVertex(0.3f, 0.1f, 0.2f, 1.0f), q = clipVertex(1.7f, 0.37f, -0.1f, 1.3f);
  const ClipVertex r = clipVertex(0.1f, 0.9f, 0.0f, 1.0f), s = clipVertex(0.2f, -0.8f, 0.1f, 1.1f);
  const ClipVertex t1[3] = {p, q, r}, t2[3] = {q, p, s};
  ClipVertex out1[kMaxClippedPolygonVertices + 3], out2[kMaxClippedPolygonVertices + 3];
  const int n1 = clipPolygon(t1, 3, withVaryings(0), out1), n2 = clipPolygon(t2, 3, withVaryings(0), out2);
  int shared = 0;
  for (int i = 0; i < n1; ++i)
    for (int j = 0; j < n2; ++j)
      if (out1[i].clip[0] == out1[i].clip[3] && std::memcmp(out1[i].clip, out2[j].clip, sizeof(out1[i].clip)) == 0) ++shared;
  CHECK(shared == 1);
}

TEST_CASE("clip: segments") {
  ClipSettings settings;
  ClipVertex a = clipVertex(-3, 0, 0, 1), b = clipVertex(3, 0, 0, 1);
  REQUIRE(clipLine(a, b, settings));
  CHECK(a.clip[0] == doctest::Approx(-1.0f));
  CHECK(b.clip[0] == doctest::Approx(1.0f));
  ClipVertex c = clipVertex(2, 0, 0, 1), d = clipVertex(3, 5, 0, 1);
  CHECK_FALSE(clipLine(c, d, settings));
  // Outside two different planes, missing the frustum's corner.
  ClipVertex e = clipVertex(0.5f, 3, 0, 1), f = clipVertex(3, 0.5f, 0, 1);
  CHECK_FALSE(clipLine(e, f, settings));
}

TEST_CASE("clip: frustum outcodes of a batch are each vertex's outcode, for any coordinates") {
  // Coordinates on the planes (w + x = 0 exactly, signed zeros), beyond them, huge, tiny,
  // infinite and NaN, in every combination the random draw makes.
  const float special[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f, 2.0f, -2.0f, 1e-40f, -1e-40f,
                           3.4e38f, -3.4e38f, INFINITY, -INFINITY, NAN};
  constexpr int kCount = 4096;
  std::vector<float> rows[4];
  std::vector<ClipVertex> vertices(kCount);
  uint32_t state = 12345;
  auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  for (int i = 0; i < kCount; ++i) {
    float c[4];
    for (float& value : c)
      value = next() % 4 == 0 ? (static_cast<float>(next() % 2001) - 1000.0f) / 250.0f
                              : special[next() % (sizeof special / sizeof special[0])];
    vertices[i] = clipVertex(c[0], c[1], c[2], c[3]);
    for (int r = 0; r < 4; ++r) rows[r].push_back(c[r]);
  }
  std::vector<unsigned> codes(kCount);
  // Batches of every length up to 64, as the vertex stage hands them over, then the rest.
  int done = 0;
  for (int length = 1; done < kCount; length = length % 64 + 1) {
    const int n = std::min(length, kCount - done);
    frustumOutcodes(rows[0].data() + done, rows[1].data() + done, rows[2].data() + done, rows[3].data() + done, n,
                    codes.data() + done);
    done += n;
  }
  int mismatches = 0, notFinite = 0, inside = 0;
  for (int i = 0; i < kCount; ++i) {
    const float* c = vertices[i].clip;
    unsigned expected = 0x3Fu | kNotFinite;
    if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3])) {
      expected = 0;
      for (int axis = 0; axis < 3; ++axis) {
        if (!(c[3] + c[axis] >= 0.0f)) expected |= 1u << (2 * axis);
        if (!(c[3] - c[axis] >= 0.0f)) expected |= 1u << (2 * axis + 1);
      }
    }
    if (codes[i] != expected || outcode(vertices[i], ClipSettings{}) != expected) ++mismatches;
    notFinite += (expected & kNotFinite) != 0;
    inside += expected == 0;
  }
  CHECK(mismatches == 0);
  CHECK(notFinite > kCount / 10);  // the draw reaches every case
  CHECK(inside > kCount / 100);
}
