// Reading Wings3D files (see glass/scene/wings_file.h for the format).
#include "glass/scene/wings_file.h"

#include "glass/scene/erlang_term.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

namespace glass::scene {

namespace {

constexpr char kHeader[] = "#!WINGS-1.0\r\n\032\04";
constexpr std::size_t kHeaderSize = sizeof(kHeader) - 1;

[[noreturn]] void fail(const std::string &message) { throw WingsFileError(message); }

double bigEndianDouble(const std::string &bytes, std::size_t at) {
  std::uint64_t bits = 0;
  for (std::size_t i = 0; i < 8; ++i) bits = (bits << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return std::bit_cast<double>(bits);
}

// Where in the file a problem is: "object 'Cube1', edge 12".
struct Place {
  std::string object;
  std::string operator()(const std::string &field) const { return "object '" + object + "', " + field; }
};

const ErlangTerm &expectList(const ErlangTerm &t, const std::string &where) {
  if (t.kind != ErlangTerm::Kind::List) fail(where + " should be a list, not " + t.describe());
  return t;
}

std::int64_t expectIndex(const ErlangTerm &t, std::size_t limit, const std::string &where, const std::string &what) {
  if (t.kind != ErlangTerm::Kind::Integer) fail(where + ": " + what + " should be an integer, not " + t.describe());
  if (t.integer < 0 || static_cast<std::uint64_t>(t.integer) >= limit)
    fail(where + ": " + what + " " + std::to_string(t.integer) + " is out of range (there are " + std::to_string(limit) + ")");
  return t.integer;
}

// A list of integers, written either as a list or, when all are below 256, as a string.
std::vector<ErlangTerm> integersOf(const ErlangTerm &t) {
  if (t.kind != ErlangTerm::Kind::String) return t.items;
  std::vector<ErlangTerm> out;
  for (unsigned char c : t.text) {
    ErlangTerm i;
    i.integer = c;
    out.push_back(i);
  }
  return out;
}

struct WingedEdge {
  std::size_t vs = 0, ve = 0, lf = 0, rf = 0, ltsu = 0, rtsu = 0;
  std::optional<glm::dvec2> uvLeft, uvRight;
};

std::optional<glm::dvec2> uvOf(const ErlangTerm &value, const std::string &where) {
  if (value.kind != ErlangTerm::Kind::Binary || value.text.size() != 16)
    fail(where + " should be a binary of two 64-bit floats, not " + value.describe());
  return glm::dvec2(bigEndianDouble(value.text, 0), bigEndianDouble(value.text, 8));
}

std::vector<WingedEdge> readEdges(const ErlangTerm &list, std::size_t vertices, std::size_t faces, const Place &place) {
  expectList(list, place("the edge table"));
  std::vector<WingedEdge> edges;
  const std::size_t count = list.items.size();
  for (std::size_t i = 0; i < count; ++i) {
    const std::string where = place("edge " + std::to_string(i));
    const ErlangTerm &data = expectList(list.items[i], where);
    bool found = false;
    WingedEdge edge;
    for (const ErlangTerm &item : data.items) {
      if (item.isTagged("edge", 9)) {
        edge.vs = static_cast<std::size_t>(expectIndex(item.items[1], vertices, where, "start vertex"));
        edge.ve = static_cast<std::size_t>(expectIndex(item.items[2], vertices, where, "end vertex"));
        edge.lf = static_cast<std::size_t>(expectIndex(item.items[3], faces, where, "left face"));
        edge.rf = static_cast<std::size_t>(expectIndex(item.items[4], faces, where, "right face"));
        expectIndex(item.items[5], count, where, "left predecessor");
        edge.ltsu = static_cast<std::size_t>(expectIndex(item.items[6], count, where, "left successor"));
        expectIndex(item.items[7], count, where, "right predecessor");
        edge.rtsu = static_cast<std::size_t>(expectIndex(item.items[8], count, where, "right successor"));
        found = true;
      } else if (item.isTagged("uv_lt", 2)) {
        edge.uvLeft = uvOf(item.items[1], where + ", uv_lt");
      } else if (item.isTagged("uv_rt", 2)) {
        edge.uvRight = uvOf(item.items[1], where + ", uv_rt");
      }
    }
    if (!found) fail(where + " has no {edge, Vs, Ve, Lf, Rf, Ltpr, Ltsu, Rtpr, Rtsu} record: " + data.describe());
    edges.push_back(edge);
  }
  return edges;
}

std::vector<glm::dvec3> readVertices(const ErlangTerm &list, const Place &place) {
  expectList(list, place("the vertex table"));
  std::vector<glm::dvec3> vertices;
  for (std::size_t i = 0; i < list.items.size(); ++i) {
    const std::string where = place("vertex " + std::to_string(i));
    const ErlangTerm &data = expectList(list.items[i], where);
    const ErlangTerm *position = nullptr;
    for (const ErlangTerm &item : data.items)
      if (item.kind == ErlangTerm::Kind::Binary && item.text.size() == 24) position = &item;
    if (position == nullptr) fail(where + " has no position (a binary of three 64-bit floats): " + data.describe());
    glm::dvec3 p(bigEndianDouble(position->text, 0), bigEndianDouble(position->text, 8), bigEndianDouble(position->text, 16));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail(where + " has a position that is not finite");
    vertices.push_back(p);
  }
  return vertices;
}

int materialIndex(const std::vector<WingsMaterial> &materials, const std::string &name) {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

WingsObject readObject(const ErlangTerm &shape, std::size_t number, const std::vector<WingsMaterial> &materials) {
  if (!shape.isTagged("object", 4))
    fail("shape " + std::to_string(number) + " should be {object, Name, {winged, ...}, Props}, not " + shape.describe());
  WingsObject object;
  if (!shape.items[1].asText(object.name)) fail("shape " + std::to_string(number) + " has a name that is not text: " + shape.items[1].describe());
  const Place place{object.name};
  const ErlangTerm &winged = shape.items[2];
  if (!winged.isTagged("winged", 5))
    fail(place("the mesh should be {winged, Edges, Faces, Vertices, HardEdges}, not " + winged.describe()));
  const ErlangTerm &faceList = expectList(winged.items[2], place("the face table"));
  const std::size_t faceCount = faceList.items.size();
  auto &shapeOut = object.shape;
  shapeOut.vertices = readVertices(winged.items[3], place);
  const std::vector<WingedEdge> edges = readEdges(winged.items[1], shapeOut.vertices.size(), faceCount, place);

  std::vector<bool> hole(faceCount, false);
  if (shape.items[3].kind == ErlangTerm::Kind::List) {
    for (const ErlangTerm &prop : shape.items[3].items) {
      if (!prop.isTagged("holes", 2) || !prop.items[1].isList()) continue;
      for (const ErlangTerm &f : integersOf(prop.items[1])) hole[static_cast<std::size_t>(expectIndex(f, faceCount, place("holes"), "face"))] = true;
    }
  }

  const int defaultMaterial = materialIndex(materials, "default");
  std::vector<std::optional<std::size_t>> firstEdge(faceCount);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!firstEdge[edges[e].lf]) firstEdge[edges[e].lf] = e;
    if (!firstEdge[edges[e].rf]) firstEdge[edges[e].rf] = e;
  }
  for (std::size_t f = 0; f < faceCount; ++f) {
    const std::string where = place("face " + std::to_string(f));
    const ErlangTerm &data = expectList(faceList.items[f], where);
    if (hole[f]) continue;
    geometry::MarkedPolyhedron::Face face;
    face.material = defaultMaterial;
    for (const ErlangTerm &item : data.items) {
      if (!item.isTagged("material", 2)) continue;
      std::string name;
      if (!item.items[1].asText(name)) fail(where + ": the material name is not text: " + item.items[1].describe());
      face.material = materialIndex(materials, name);
    }
    if (!firstEdge[f]) fail(where + " has no edges");
    // The walk by successors, then reversed: counter-clockwise seen from outside.
    std::vector<std::uint32_t> walked;
    std::vector<std::optional<glm::dvec2>> uvs;
    std::size_t e = *firstEdge[f];
    for (std::size_t steps = 0;; ++steps) {
      if (steps > edges.size()) fail(where + ": its edge loop does not close");
      const WingedEdge &edge = edges[e];
      if (edge.lf == f) {
        walked.push_back(static_cast<std::uint32_t>(edge.vs));
        uvs.push_back(edge.uvLeft);
        e = edge.ltsu;
      } else if (edge.rf == f) {
        walked.push_back(static_cast<std::uint32_t>(edge.ve));
        uvs.push_back(edge.uvRight);
        e = edge.rtsu;
      } else {
        fail(where + ": its edge loop reaches edge " + std::to_string(e) + ", which does not border it");
      }
      if (e == *firstEdge[f]) break;
    }
    if (walked.size() < 3) fail(where + " has only " + std::to_string(walked.size()) + " vertices");
    face.vertices.assign(walked.rbegin(), walked.rend());
    const bool allUvs = std::all_of(uvs.begin(), uvs.end(), [](const auto &uv) { return uv.has_value(); });
    if (allUvs)
      for (auto it = uvs.rbegin(); it != uvs.rend(); ++it) face.uvs.push_back(**it);
    shapeOut.faces.push_back(std::move(face));
  }

  const ErlangTerm &hard = winged.items[4];
  if (!hard.isList()) fail(place("the hard edge list should be a list, not " + hard.describe()));
  for (const ErlangTerm &h : integersOf(hard)) {
    const auto e = static_cast<std::size_t>(expectIndex(h, edges.size(), place("the hard edge list"), "edge"));
    shapeOut.markedEdges.push_back({static_cast<std::uint32_t>(edges[e].vs), static_cast<std::uint32_t>(edges[e].ve)});
  }
  return object;
}

void readColor(const ErlangTerm &value, std::array<float, 4> &out, const std::string &where) {
  if (value.kind != ErlangTerm::Kind::Tuple || (value.items.size() != 3 && value.items.size() != 4))
    fail(where + " should be {R, G, B, A}, not " + value.describe());
  for (std::size_t i = 0; i < value.items.size(); ++i) {
    double component = 0.0;
    if (!value.items[i].asNumber(component)) fail(where + " has a component that is not a number: " + value.describe());
    out[i] = static_cast<float>(component);
  }
}

WingsMaterial readMaterial(const ErlangTerm &entry, std::size_t number) {
  const std::string where = "material " + std::to_string(number);
  if (entry.kind != ErlangTerm::Kind::Tuple || entry.items.size() != 2 || !entry.items[1].isList())
    fail(where + " should be {Name, Properties}, not " + entry.describe());
  WingsMaterial material;
  if (!entry.items[0].asText(material.name)) fail(where + " has a name that is not text: " + entry.items[0].describe());
  const std::string named = "material '" + material.name + "'";
  for (const ErlangTerm &group : entry.items[1].items) {
    if (!group.isTagged("opengl", 2)) continue;
    if (!group.items[1].isList()) fail(named + ": the opengl properties should be a list, not " + group.items[1].describe());
    for (const ErlangTerm &prop : group.items[1].items) {
      if (prop.kind != ErlangTerm::Kind::Tuple || prop.items.size() != 2 || prop.items[0].kind != ErlangTerm::Kind::Atom) continue;
      const std::string &key = prop.items[0].text;
      if (key == "diffuse") readColor(prop.items[1], material.diffuse, named + ", diffuse");
      else if (key == "ambient") readColor(prop.items[1], material.ambient, named + ", ambient");
      else if (key == "specular") readColor(prop.items[1], material.specular, named + ", specular");
      else if (key == "emission") readColor(prop.items[1], material.emission, named + ", emission");
      else if (key == "shininess") {
        double s = 0.0;
        if (!prop.items[1].asNumber(s) || !(s >= 0.0 && s <= 1.0))
          fail(named + ", shininess should be a number from 0 to 1, not " + prop.items[1].describe());
        material.shininess = static_cast<float>(128.0 * s);
      }
    }
  }
  return material;
}

} // namespace

WingsFile parseWingsFile(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kHeaderSize || std::memcmp(bytes.data(), kHeader, kHeaderSize) != 0)
    fail("not a Wings file: it does not start with the header #!WINGS-1.0");
  if (bytes.size() < kHeaderSize + 4) fail("the file ends inside its header");
  const auto *size = bytes.data() + kHeaderSize;
  const std::size_t claimed = (std::size_t{size[0]} << 24) | (std::size_t{size[1]} << 16) | (std::size_t{size[2]} << 8) | size[3];
  const std::span<const std::uint8_t> data = bytes.subspan(kHeaderSize + 4);
  if (data.size() != claimed)
    fail("the header announces " + std::to_string(claimed) + " bytes of data but the file holds " + std::to_string(data.size()) +
         (data.size() < claimed ? " (cut short)" : ""));
  ErlangTerm top;
  try {
    top = decodeErlangTerm(data);
  } catch (const ErlangTermError &error) {
    fail(std::string("the data is not a readable Erlang term: ") + error.what());
  }
  if (top.kind != ErlangTerm::Kind::Tuple || top.items.size() != 3 || !top.items[0].isAtom("wings") ||
      top.items[1].kind != ErlangTerm::Kind::Integer)
    fail("the data should be {wings, Version, Contents}, not " + top.describe());
  if (top.items[1].integer != 2)
    fail("Wings format version " + std::to_string(top.items[1].integer) + " is not supported (version 2 is, as written since Wings 0.92)");
  const ErlangTerm &contents = top.items[2];
  if (contents.kind != ErlangTerm::Kind::Tuple || contents.items.size() != 3)
    fail("the contents should be {Shapes, Materials, Properties}, not " + contents.describe());
  WingsFile file;
  const ErlangTerm &materials = contents.items[1];
  if (!materials.isList()) fail("the material list should be a list, not " + materials.describe());
  for (std::size_t i = 0; i < materials.items.size(); ++i) file.materials.push_back(readMaterial(materials.items[i], i));
  const ErlangTerm &shapes = contents.items[0];
  if (!shapes.isList()) fail("the shape list should be a list, not " + shapes.describe());
  for (std::size_t i = 0; i < shapes.items.size(); ++i) file.objects.push_back(readObject(shapes.items[i], i, file.materials));
  return file;
}

WingsFile readWingsFile(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw WingsFileError(path + ": cannot open the file");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return parseWingsFile(bytes);
  } catch (const WingsFileError &error) {
    throw WingsFileError(path + ": " + error.what());
  }
}

} // namespace glass::scene
