// Wings3D models in scenes: the objects of a .wings file (glass/scene/wings_file.h), drawn sharp or
// with their marked edges rounded (glass/geometry/edge_rounding.h) at the radius of the frame.
#pragma once

#include "glass/scene/program.h"
#include "glass/scene/wings_file.h"
#include "load/rounded_parts_cache.h"

#include <string>
#include <vector>

namespace glass::scene {

struct RoundableModel {
  std::vector<WingsObject> objects;
  // The rounded parts of the radii drawn last (drawing and checking a radius go through it).
  mutable RoundedPartsCache rounded;
};

// Reads `path` into `model`: its materials, its objects drawn sharp as model.parts, and the
// objects themselves in model.roundable. Returns false with a reason (naming the object and field,
// not the file) on failure.
bool loadWingsModel(const std::string &path, Model &model, std::string &reason);

// The triangles of every object rounded with `radius`, grouped by material (indices into the
// model's materials). Throws geometry::RoundingError, its message naming the object.
std::vector<ModelPart> roundedWingsParts(const RoundableModel &model, double radius);

// What is wrong with the model's objects as solids (geometry/polyhedron_check.h), one message
// each, naming the object: open, faces turned unlike their neighbours, inside out, crossing
// itself; or that the file has no objects. Such a model still draws, as the file gives it.
std::vector<std::string> wingsModelWarnings(const RoundableModel &model);

// A radius or a volume as messages about models give it: six significant digits.
std::string formatModelNumber(double value);

// The largest radius every object can be rounded with, and what limits it.
double largestWingsRadius(const RoundableModel &model, std::string &limit);

} // namespace glass::scene
