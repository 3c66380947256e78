// The viewer's changes to a scene (`glass view`'s menu and keys): the shade model, wireframe,
// lights switched off and the rounding radius. They are made on a copy of the parsed program,
// statement by statement, so the scene library draws the changed scene as it draws any other and
// the scene file stays as it is.
#pragma once

#include <glass/scene/program.h>

#include <string>
#include <vector>

namespace glass::cli::view {

enum class ShadeChoice { Scene, Flat, Smooth, Phong };

struct SceneOverrides {
  ShadeChoice shade = ShadeChoice::Scene; // Scene: the scene's own `shade_model` statements
  bool wireframe = false;                 // every polygon drawn as its outline
  std::vector<int> lightsOff;             // light numbers (0-7) never enabled
  double roundingChange = 0.0;            // added to every `model ... round R` radius (never below 0)

  bool any() const {
    return shade != ShadeChoice::Scene || wireframe || !lightsOff.empty() || roundingChange != 0.0;
  }
};

// A light the scene switches on (`enable lightN` somewhere), with its kind from its `light`
// statements at frame 0: "directional" (position w = 0), "spot" (spot_cutoff other than 180) or
// "point".
struct SceneLight {
  int number = 0;
  std::string kind;
};
std::vector<SceneLight> sceneLights(const scene::Program &program);

// True when the program draws a `model ... round R`.
bool hasRoundedModels(const scene::Program &program);

// The program with the overrides made, for frame `frame` (a radius given by a parameter is taken
// at that frame):
// - shade: every `shade_model` statement sets the chosen model, and one more at the start sets it
//   for what comes before any (GL_FLAT, GL_SMOOTH or glass's GL_PHONG_WIN);
// - wireframe: `polygon_mode front_and_back line` at the start, and every `polygon_mode`
//   statement sets that too;
// - lightsOff: those lights are taken out of every `enable` statement;
// - roundingChange: every rounded model's radius R becomes max(0, R + roundingChange).
scene::Program withOverrides(const scene::Program &program, const SceneOverrides &overrides, int frame);

} // namespace glass::cli::view
