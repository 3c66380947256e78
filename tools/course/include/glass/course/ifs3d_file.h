// Reading a .ifs3 file with its base model, as every `glass ifs3d` command does.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "glass/geometry/ifs3d.h"

namespace glass::course {

// The system of `file`, its `base "model.obj"` read (relative to the file); on a problem,
// `file:line:col` errors (or "cannot read FILE") on `err` and nothing.
std::optional<geometry::IteratedFunctionSystem3> loadIfs3File(const std::string& file, std::ostream& err);

}  // namespace glass::course
