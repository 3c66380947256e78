#include "glass/scene/ifs3_base_model.h"

#include <filesystem>
#include <vector>

#include "load/obj_model.h"

namespace glass::scene {

std::optional<geometry::IfsParseError> loadIfs3BaseModel(geometry::IteratedFunctionSystem3 &ifs,
                                                         const std::string &ifsFilePath) {
  if (ifs.base != geometry::IfsBase3::Model) return std::nullopt;
  const std::filesystem::path written(ifs.baseModelPath);
  const std::filesystem::path path =
      written.is_absolute() ? written : std::filesystem::path(ifsFilePath).parent_path() / written;
  const auto failure = [&](const std::string &message) {
    return geometry::IfsParseError{ifs.baseModelLine, ifs.baseModelColumn, message};
  };
  Model model;
  std::vector<TextureDefinition> textures; // the base is drawn in the maps' colours: textures unused
  std::string reason;
  if (!loadObjModel(path.string(), model, textures, reason)) {
    return failure("cannot read the base model '" + path.string() + "': " + reason);
  }
  ifs.baseModel.clear();
  for (const ModelPart &part : model.parts) {
    // Three vertices a triangle, three floats a vertex; the OBJ's counter-clockwise faces face out.
    for (std::size_t v = 0; v + 9 <= part.positions.size(); v += 9) {
      const float *p = &part.positions[v];
      ifs.baseModel.push_back({{p[0], p[1], p[2]}, {p[3], p[4], p[5]}, {p[6], p[7], p[8]}});
    }
  }
  if (ifs.baseModel.empty()) return failure("the base model '" + path.string() + "' has no faces");
  return std::nullopt;
}

} // namespace glass::scene
