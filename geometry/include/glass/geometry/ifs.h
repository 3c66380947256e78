// Iterated function systems of the plane (section 2.2.2 of the study guide): a list of affine maps
// f1..fr whose Hutchinson operator H(X) = f1(X) u ... u fr(X) has the fractal F = H(F) as its
// fixed point. Two ways to draw F, both deterministic:
//  - expansion to depth n: H applied n times to a base figure, i.e. the base figure drawn once
//    through each of the r^n composites f_i1 o ... o f_in. Written as the guide's Listing 4, a
//    recursion that pushes, multiplies and pops a matrix stack, so a GL program can follow it
//    with glPushMatrix / glMultMatrixd / glPopMatrix;
//  - the chaos game (the guide's "probability approach"): x_{k+1} = f_i(x_k) with the map i drawn
//    at random with probability p_i, from a seeded generator.
// The part of F drawn through map i first, f_i(F), is "part i"; each part has its own colour.
//
// The model is shared by the `glass ifs` tool and the scene language's `ifs` statement; the file
// format is in ifs_format.h, dimensions in ifs_dimension.h.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "glass/geometry/affine2d.h"

namespace glass::geometry {

struct IfsColor {
  float r = 1.0f, g = 1.0f, b = 1.0f;
  bool operator==(const IfsColor&) const = default;
};

struct IfsMap {
  Affine2 transform;
  std::optional<double> probability;  // chaos game weight; none: see chaosGameProbabilities
  std::optional<IfsColor> color;      // colour of this map's part; none: see partColor
};

// The rectangle of the plane shown in the picture: glOrtho(xMin, xMax, yMin, yMax, -1, 1).
struct IfsWindow {
  double xMin = -0.1, xMax = 1.1, yMin = -0.1, yMax = 1.1;  // Listing 5's constants
  bool operator==(const IfsWindow&) const = default;
};

struct IteratedFunctionSystem {
  std::string name;
  std::vector<IfsMap> maps;
  // The step-0 figure, a filled convex polygon given counter-clockwise; Listing 4
  // draws the triangle (1,0), (0,1), (0,0). By default the unit square.
  std::vector<glm::dvec2> base{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  std::optional<IfsWindow> window;  // none: fitted to the attractor (attractorWindow)
};

// Limits shared by every renderer of an IFS, so that a typo cannot ask for years of drawing.
inline constexpr std::uint64_t kMaxIfsBaseCopies = std::uint64_t{1} << 24;  // r^depth
inline constexpr std::uint64_t kMaxChaosGamePoints = 200'000'000;

// r^depth, the number of base figures the expansion draws, saturated at UINT64_MAX.
std::uint64_t ifsBaseCopies(const IteratedFunctionSystem& ifs, int depth);

// The colour of part i: the map's own colour, or else entry i of a fixed palette of distinct
// colours.
IfsColor partColor(const IteratedFunctionSystem& ifs, std::size_t part);

// The chaos game's probabilities, summing to 1. Given ones are normalised. When none is given,
// p_i is proportional to |det L_i|, the share of area map i keeps (Barnsley's rule, which spreads
// the points evenly), with each map given at least 1/100 of the largest share so that a map that
// flattens the plane onto a line, like the fern's stem, still gets points. Empty when some maps
// have probabilities and some do not, or a probability is negative, or all are zero.
std::optional<std::vector<double>> chaosGameProbabilities(const IteratedFunctionSystem& ifs);

// The Listing 4 recursion, as calls on a matrix stack. At depth 0 drawBase is called with the
// current part (-1 when the whole system is drawn at depth 0, so no map has been applied yet).
// Otherwise, for each map i in order: pushMatrix, multiplyMatrix(f_i), recurse with depth - 1,
// popMatrix. The part of a base figure is the map chosen at the outermost level.
class IfsMatrixStackVisitor {
 public:
  virtual ~IfsMatrixStackVisitor() = default;
  virtual void pushMatrix() = 0;
  virtual void multiplyMatrix(const Affine2& map) = 0;
  virtual void popMatrix() = 0;
  virtual void drawBase(int part) = 0;
};

// depth >= 0; the caller checks ifsBaseCopies against its limit first.
void expandIfs(const IteratedFunctionSystem& ifs, int depth, IfsMatrixStackVisitor& visitor);

// The same expansion as a list of composite maps f_i1 o ... o f_in with their parts, in the
// order the recursion draws them. For tests and for analyses without GL.
struct IfsComposite {
  Affine2 transform;
  int part = -1;
};
std::vector<IfsComposite> ifsComposites(const IteratedFunctionSystem& ifs, int depth);

// The chaos game: `count` points of the attractor. It starts at the fixed point of the first map
// with a unique one (a point of F), runs 100 steps unrecorded so that any start is forgotten,
// then reports each point with the map that produced it, which is the part it lies in.
// Preconditions: probabilities as returned by chaosGameProbabilities, non-empty maps.
void chaosGame(const IteratedFunctionSystem& ifs, const std::vector<double>& probabilities,
               std::uint64_t count, std::uint64_t seed,
               const std::function<void(const glm::dvec2& point, int part)>& visit);

struct IfsPoint {
  glm::dvec2 position;
  int part = 0;
};
std::vector<IfsPoint> chaosGamePoints(const IteratedFunctionSystem& ifs,
                                      const std::vector<double>& probabilities,
                                      std::uint64_t count, std::uint64_t seed);

// The fixed point x = f(x) of an affine map, when (I - L) is invertible.
std::optional<glm::dvec2> fixedPoint(const Affine2& map);

// A window around the attractor: the bounding box of the fixed points of all compositions of up
// to a few maps (all of them points of F) and of a fixed-seed chaos game, grown by 10% of its
// size on every side, as Listing 5's window [-0.1, 1.1] around the unit square.
IfsWindow attractorWindow(const IteratedFunctionSystem& ifs);

// Listing 5's resizeWindow: the window grown about its centre along one axis so that its aspect
// ratio matches a width x height viewport, so the fractal is scaled uniformly, never stretched.
IfsWindow fitWindowToAspect(const IfsWindow& window, int width, int height);

}  // namespace glass::geometry
