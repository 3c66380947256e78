#include "texture/bump_mapping.h"

#include <cmath>

#include "texture/texture_sampler.h"

namespace glass::gl {
namespace {

void cross(const double a[3], const double b[3], double out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double length(const double a[3]) { return std::sqrt(dot(a, a)); }

// The height d at (s, t): the base level, filtered with the texture's magnification filter.
double heightAt(const TextureObject& heightMap, float scale, float s, float t) {
  float texel[4];
  sampleTextureMagnified(heightMap, s, t, texel);
  return static_cast<double>(scale) * texel[0];
}

}  // namespace

void perturbNormalByHeightMap(const TextureObject& heightMap, float scale, float s, float t,
                              const TexCoordDerivatives& st, const double dPdx[3],
                              const double dPdy[3], float normal[3]) {
  // P_s and P_t from dP/dx = P_s s_x + P_t t_x, dP/dy = P_s s_y + P_t t_y (Cramer's rule).
  const double det = st.dsdx * st.dtdy - st.dtdx * st.dsdy;
  if (!(std::fabs(det) > 1e-20)) return;
  double ps[3], pt[3];
  for (int k = 0; k < 3; ++k) {
    ps[k] = (st.dtdy * dPdx[k] - st.dtdx * dPdy[k]) / det;
    pt[k] = (st.dsdx * dPdy[k] - st.dsdy * dPdx[k]) / det;
  }
  double tangentCross[3];
  cross(ps, pt, tangentCross);
  const double area = length(tangentCross);
  const double n0[3] = {normal[0], normal[1], normal[2]};
  const double normalLength = length(n0);
  if (!(area > 0.0) || !(normalLength > 0.0)) return;
  const double n[3] = {n0[0] / normalLength, n0[1] / normalLength, n0[2] / normalLength};
  // Orient P_s x P_t along the given normal: texture axes may run either way round.
  const double orientation = dot(tangentCross, n) < 0.0 ? -1.0 : 1.0;

  // d_s, d_t: central differences one base-level texel apart.
  const TextureImage& base = heightMap.baseImage();
  const double hs = 1.0 / base.width, ht = 1.0 / base.height;
  const double ds = (heightAt(heightMap, scale, static_cast<float>(s + hs), t) -
                     heightAt(heightMap, scale, static_cast<float>(s - hs), t)) / (2.0 * hs);
  const double dt = (heightAt(heightMap, scale, s, static_cast<float>(t + ht)) -
                     heightAt(heightMap, scale, s, static_cast<float>(t - ht))) / (2.0 * ht);

  double nxPt[3], nxPs[3];
  cross(n, pt, nxPt);
  cross(n, ps, nxPs);
  double perturbed[3];
  for (int k = 0; k < 3; ++k) perturbed[k] = n[k] + orientation * (ds * nxPt[k] - dt * nxPs[k]) / area;
  const double perturbedLength = length(perturbed);
  if (!(perturbedLength > 0.0)) return;
  for (int k = 0; k < 3; ++k) normal[k] = static_cast<float>(perturbed[k] / perturbedLength * normalLength);
}

}  // namespace glass::gl
