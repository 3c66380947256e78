// `ifs3d "F.ifs3" [depth N] [colors on|off] [map K step T]`: the polyhedral rebuild of a 3D IFS
// (study guide, homework 3), read from a .ifs3 file (glass/geometry/ifs3d_format.h), the format
// `glass ifs3d` reads and writes.
#include "parser_impl.h"

#include <glass/geometry/ifs3d.h>
#include <glass/geometry/ifs3d_format.h>
#include <glass/scene/ifs3_base_model.h>

#include <algorithm>
#include <memory>

namespace glass::scene {

void Parser::parseIfs3d(StatementReader &r) {
  static const ParamSpec specs[] = {
      {"depth", ParamKind::Integer, 0, 12, {}, ""},
      {"colors", ParamKind::Boolean, 1, 1, {}, ""},
      {"map", ParamKind::Integer, 1, 64, {}, ""},
      {"step", ParamKind::Numbers, 1, 1, {}, "0 (the identity) to 1 (the map)"},
  };
  const Token &fileToken = r.peek();
  const std::string written = r.string("the .ifs3 file");
  NamedParams params = NamedParams::read(r, specs);
  Ifs3d ifs;
  ifs.depth = static_cast<int>(params.integerOr("depth", 3));
  ifs.partColors = params.booleanOr("colors", true);
  const ParamValue *map = params.take("map");
  const ParamValue *step = params.take("step");
  if ((map == nullptr) != (step == nullptr)) {
    const ParamValue *given = map != nullptr ? map : step;
    r.fail(given->where, given->length, "'map K' and 'step T' go together: the step of map K's animation");
  }
  if (step != nullptr) ifs.step = step->numbers.at(0);
  const std::string path = resolvePath(written, fileToken.where);
  geometry::Ifs3ParseResult loaded = geometry::loadIfs3File(path);
  if (loaded.ok()) {
    if (auto problem = loadIfs3BaseModel(loaded.ifs, path)) loaded.errors.push_back(std::move(*problem));
  }
  if (!loaded.ok()) {
    const geometry::IfsParseError &first = loaded.errors.front();
    r.fail(fileToken.where, static_cast<int>(written.size()) + 2,
           "cannot use IFS file '" + path + "': " +
               (first.line > 0 ? "line " + std::to_string(first.line) + ":" + std::to_string(first.column) + ": " : "") +
               first.message);
  }
  if (map != nullptr) {
    if (map->integer > static_cast<long long>(loaded.ifs.maps.size())) {
      r.fail(map->where, map->length,
             "the file has " + std::to_string(loaded.ifs.maps.size()) + " maps; there is no map " + std::to_string(map->integer));
    }
    ifs.animatedMap = static_cast<int>(map->integer) - 1;
  }
  const std::uint64_t copies = geometry::ifs3BaseCopies(loaded.ifs, ifs.depth);
  const std::uint64_t baseTriangles = geometry::basePolyhedron(loaded.ifs).size();
  if (copies > geometry::kMaxRebuildTriangles / std::max<std::uint64_t>(baseTriangles, 1)) {
    r.fail(r.statementToken(), "'ifs3d' at depth " + std::to_string(ifs.depth) + " would draw " + std::to_string(baseTriangles) +
                                   " x " + std::to_string(loaded.ifs.maps.size()) + "^" + std::to_string(ifs.depth) +
                                   " triangles; the limit is " + std::to_string(geometry::kMaxRebuildTriangles) +
                                   " (lower the depth)");
  }
  ifs.system = std::make_shared<const geometry::IteratedFunctionSystem3>(std::move(loaded.ifs));
  params.requireAllUsed(r);
  emit(r, std::move(ifs));
}

} // namespace glass::scene
