// Wavefront OBJ models with their MTL materials, read by tinyobjloader (Debian's
// libtinyobjloader-dev: a well-kept loader, so glass does not write its own).
#pragma once

#include "glass/scene/program.h"

#include <string>
#include <vector>

namespace glass::scene {

// Reads `path`, triangulates its faces and groups the triangles by material. Textures named by
// the materials (map_Kd) are read and appended to `textures`; the model's materials point into it.
// Faces without normals get their face normal. Returns false with a reason on failure.
bool loadObjModel(const std::string &path, Model &model, std::vector<TextureDefinition> &textures,
                  std::string &reason);

} // namespace glass::scene
