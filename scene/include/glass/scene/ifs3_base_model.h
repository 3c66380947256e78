// The base polyhedron of a 3D IFS read from an OBJ file (`base "model.obj"` in a .ifs3 file,
// glass/geometry/ifs3d_format.h), through the scene language's OBJ reader, so that `glass ifs3d`
// and the `ifs3d` statement read models exactly as the `model` statement does.
#pragma once

#include <optional>
#include <string>

#include <glass/geometry/ifs3d.h>
#include <glass/geometry/ifs_format.h>

namespace glass::scene {

// When ifs.base is IfsBase3::Model, reads ifs.baseModelPath (relative to the directory of
// `ifsFilePath`, the .ifs3 file) and fills ifs.baseModel with its triangles. Returns an error
// at the line and column of the file name in the .ifs3 file when the model cannot be read or has
// no triangles; nothing otherwise (and for every other base).
std::optional<geometry::IfsParseError> loadIfs3BaseModel(geometry::IteratedFunctionSystem3 &ifs,
                                                         const std::string &ifsFilePath);

} // namespace glass::scene
