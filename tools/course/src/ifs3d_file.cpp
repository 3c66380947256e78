#include "glass/course/ifs3d_file.h"

#include <glass/scene/ifs3_base_model.h>

#include "glass/geometry/ifs3d_format.h"

namespace glass::course {

namespace g = glass::geometry;

std::optional<g::IteratedFunctionSystem3> loadIfs3File(const std::string& file, std::ostream& err) {
  const std::optional<std::string> text = g::readIfsText(file);
  if (!text) {
    err << "glass ifs3d: cannot read " << file << "\n";
    return std::nullopt;
  }
  g::Ifs3ParseResult parsed = g::parseIfs3(*text);
  if (parsed.ok()) {
    if (auto problem = scene::loadIfs3BaseModel(parsed.ifs, file)) parsed.errors.push_back(std::move(*problem));
  }
  if (!parsed.ok()) {
    err << g::formatIfsErrors(parsed.errors, file, *text);
    return std::nullopt;
  }
  return std::move(parsed.ifs);
}

}  // namespace glass::course
