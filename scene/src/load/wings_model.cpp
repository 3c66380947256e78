// Wings3D models in scenes (see wings_model.h).
#include "load/wings_model.h"

#include "glass/geometry/polyhedron_check.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

namespace glass::scene {

namespace {

// Curved pieces are split until their control points are within this share of the radius of the
// flat piece between their corners: a quarter circle becomes 8 segments (chords within 0.5 % of
// R of the arc), as examples/homework45 draws its arcs (ARC_STEPS). At 0.2 % it became 32, four
// times the triangles along every arc, for pictures no different at the usual sizes (the room
// at 800 x 600: 2 pixels by more than 8/255) and frames twice as long.
constexpr double kRelativeDeviation = 0.01;

void appendTriangles(const geometry::MarkedPolyhedron &shape, const geometry::RoundedMesh &rounded,
                     std::map<int, ModelPart> &byMaterial) {
  const auto &mesh = rounded.mesh;
  for (std::size_t t = 0; t < rounded.triangleFaces.size(); ++t) {
    const int material = shape.faces[static_cast<std::size_t>(rounded.triangleFaces[t])].material;
    ModelPart &part = byMaterial[material];
    part.material = material;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = mesh.indices[3 * t + static_cast<std::size_t>(k)];
      for (int c = 0; c < 3; ++c) {
        part.positions.push_back(static_cast<float>(mesh.positions[i][c]));
        part.normals.push_back(static_cast<float>(mesh.normals[i][c]));
      }
      part.texcoords.push_back(static_cast<float>(mesh.texCoords[i].x));
      part.texcoords.push_back(static_cast<float>(mesh.texCoords[i].y));
    }
  }
}

} // namespace

std::string formatModelNumber(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

std::vector<ModelPart> roundedWingsParts(const RoundableModel &model, double radius) {
  std::map<int, ModelPart> byMaterial;
  for (const WingsObject &object : model.objects) {
    try {
      const geometry::RoundedSurface surface = geometry::roundMarkedEdges(object.shape, radius);
      geometry::AdaptiveOptions options;
      options.criterion = geometry::ObjectSpaceTolerance{radius > 0.0 ? kRelativeDeviation * radius : 1.0};
      options.maxDepth = 6;
      appendTriangles(object.shape, geometry::tessellateRounded(object.shape, surface, options), byMaterial);
    } catch (const geometry::RoundingError &error) {
      throw geometry::RoundingError("object '" + object.name + "': " + error.what());
    }
  }
  std::vector<ModelPart> parts;
  for (auto &[material, part] : byMaterial) parts.push_back(std::move(part));
  return parts;
}

std::vector<std::string> wingsModelWarnings(const RoundableModel &model) {
  std::vector<std::string> warnings;
  if (model.objects.empty()) warnings.push_back("the file has no objects: nothing is drawn");
  const auto edge = [](const std::array<std::uint32_t, 2> &e) {
    return "between vertices " + std::to_string(e[0]) + " and " + std::to_string(e[1]);
  };
  const auto count = [](int n, const std::string &one, const std::string &many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  for (const WingsObject &object : model.objects) {
    const geometry::PolyhedronCheck check = geometry::checkPolyhedron(object.shape);
    const std::string name = "object '" + object.name + "' ";
    if (check.openEdges > 0)
      warnings.push_back(name + "is open: " + count(check.openEdges, "edge belongs", "edges belong") +
                         " to one face only (the first " + edge(check.firstOpenEdge) + ")");
    if (check.nonManifoldEdges > 0)
      warnings.push_back(name + "is not one surface: " +
                         count(check.nonManifoldEdges, "edge belongs", "edges belong") +
                         " to three faces or more (the first " + edge(check.firstNonManifoldEdge) + ")");
    if (check.reversedEdges > 0)
      warnings.push_back(name + "has faces turned the other way round: at " +
                         count(check.reversedEdges, "edge", "edges") +
                         " the two faces run the same way (the first " + edge(check.firstReversedEdge) + ")");
    if (check.insideOut())
      warnings.push_back(name + "is inside out: its faces face inwards (volume " + formatModelNumber(check.volume) +
                         "), so lighting and culling take its inside for its outside");
    if (check.crossingFacePairs > 0)
      warnings.push_back(name + "crosses itself: " + count(check.crossingFacePairs, "pair", "pairs") +
                         " of faces cut through each other (the first faces " +
                         std::to_string(check.firstCrossing[0]) + " and " + std::to_string(check.firstCrossing[1]) + ")");
  }
  return warnings;
}

double largestWingsRadius(const RoundableModel &model, std::string &limit) {
  double largest = std::numeric_limits<double>::infinity();
  for (const WingsObject &object : model.objects) {
    std::string why;
    const double r = geometry::maximumRoundingRadius(object.shape, &why);
    if (r < largest) {
      largest = r;
      limit = "object '" + object.name + "': " + why;
    }
  }
  return largest;
}

bool loadWingsModel(const std::string &path, Model &model, std::string &reason) {
  try {
    // The scene's message names the file as the scene wrote it: the reason does not repeat it.
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      reason = "cannot open the file";
      return false;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    WingsFile file = parseWingsFile(bytes);
    model.path = path;
    model.hasNormals = true;
    for (const WingsMaterial &m : file.materials) {
      ModelMaterial material;
      material.ambient = m.ambient;
      material.diffuse = m.diffuse;
      material.specular = m.specular;
      material.emission = m.emission;
      material.shininess = m.shininess;
      model.materials.push_back(material);
    }
    auto roundable = std::make_shared<RoundableModel>();
    roundable->objects = std::move(file.objects);
    model.parts = roundedWingsParts(*roundable, 0.0);
    model.roundable = std::move(roundable);
    return true;
  } catch (const WingsFileError &error) {
    reason = error.what();
  } catch (const geometry::RoundingError &error) {
    reason = error.what();
  }
  return false;
}

} // namespace glass::scene
