// The .wings reader and the Erlang term decoder under it, on files written by Erlang's own
// term_to_binary (scenes/models/make_wings_models.escript) and on one saved by Wings3D.
#include <doctest/doctest.h>

#include "glass/scene/erlang_term.h"
#include "glass/scene/wings_file.h"

#include <glm/geometric.hpp>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using glass::scene::ErlangTerm;
using glass::scene::WingsFile;
using glass::scene::WingsFileError;

namespace {

std::string dataPath(const std::string &name) { return std::string(GLASS_SOURCE_DIR) + "/tests/unit/data/wings/" + name; }

std::vector<std::uint8_t> bytesOf(const std::string &name) {
  std::ifstream in(dataPath(name), std::ios::binary);
  REQUIRE(in);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string errorOf(const std::string &name) {
  try {
    glass::scene::readWingsFile(dataPath(name));
  } catch (const WingsFileError &error) {
    return error.what();
  }
  return "(no error)";
}

std::string parseError(std::span<const std::uint8_t> bytes) {
  try {
    glass::scene::parseWingsFile(bytes);
  } catch (const WingsFileError &error) {
    return error.what();
  }
  return "";
}

// Six times the signed volume: positive when the faces are counter-clockwise seen from outside.
double signedVolume(const glass::geometry::MarkedPolyhedron &shape) {
  double volume = 0.0;
  for (const auto &face : shape.faces)
    for (std::size_t i = 1; i + 1 < face.vertices.size(); ++i)
      volume += glm::dot(shape.vertices[face.vertices[0]],
                         glm::cross(shape.vertices[face.vertices[i]], shape.vertices[face.vertices[i + 1]]));
  return volume;
}

void checkShapes(const ErlangTerm &t) {
  REQUIRE(t.kind == ErlangTerm::Kind::Tuple);
  REQUIRE(t.items.size() == 20);
  const auto &i = t.items;
  CHECK(i[0].integer == 0);
  CHECK(i[1].integer == 255);
  CHECK(i[2].integer == 256);
  CHECK(i[3].integer == -1);
  CHECK(i[4].integer == 2147483647);
  CHECK(i[5].integer == -2147483648LL);
  CHECK(i[6].integer == (std::int64_t{1} << 40));
  CHECK(i[7].integer == -(std::int64_t{1} << 40));
  CHECK(i[8].kind == ErlangTerm::Kind::Float);
  CHECK(i[8].number == 1.5);
  CHECK(i[9].number == -0.25);
  CHECK(i[10].isAtom("atom"));
  CHECK(i[11].isAtom("\xC3\xBCn\xC3\xAF")); // 'ünï' in UTF-8, whichever atom encoding
  std::string text;
  CHECK(i[12].asText(text));
  CHECK(text == "text");
  CHECK(i[12].isList());
  REQUIRE(i[13].kind == ErlangTerm::Kind::List);
  REQUIRE(i[13].items.size() == 2);
  CHECK(i[13].items[1].integer == 2000);
  CHECK((i[14].kind == ErlangTerm::Kind::List && i[14].items.empty()));
  CHECK(i[15].kind == ErlangTerm::Kind::Binary);
  CHECK(i[15].text == std::string("\x01\x02\x03", 3));
  CHECK((i[16].kind == ErlangTerm::Kind::Tuple && i[16].items.empty()));
  REQUIRE(i[17].kind == ErlangTerm::Kind::Map);
  REQUIRE(i[17].items.size() == 2);
  CHECK(i[17].items[0].isAtom("key"));
  CHECK(i[17].items[1].isAtom("value"));
  REQUIRE(i[18].kind == ErlangTerm::Kind::Tuple);
  REQUIRE(i[18].items.size() == 300);
  CHECK(i[18].items[299].integer == 300);
  REQUIRE(i[19].kind == ErlangTerm::Kind::List);
  REQUIRE(i[19].items.size() == 300);
  CHECK(i[19].items[0].integer == 1);
}

} // namespace

TEST_CASE("Erlang terms: every shape Wings files use, as term_to_binary writes them") {
  for (const char *name : {"shapes.term", "shapes_compressed.term", "shapes_old_floats.term"}) {
    CAPTURE(name);
    checkShapes(glass::scene::decodeErlangTerm(bytesOf(name)));
  }
}

TEST_CASE("Erlang terms: broken data is refused with the byte it goes wrong at") {
  const std::vector<std::uint8_t> plain = bytesOf("shapes.term");
  for (std::size_t cut : {std::size_t{1}, std::size_t{2}, std::size_t{40}, plain.size() - 1}) {
    CAPTURE(cut);
    CHECK_THROWS_AS(glass::scene::decodeErlangTerm(std::span(plain).first(cut)), glass::scene::ErlangTermError);
  }
  std::vector<std::uint8_t> wrongVersion = plain;
  wrongVersion[0] = 130;
  CHECK_THROWS_WITH_AS(glass::scene::decodeErlangTerm(wrongVersion), doctest::Contains("first byte is not 131"),
                       glass::scene::ErlangTermError);
  // A pid (tag 88) is not a term of a Wings file.
  const std::vector<std::uint8_t> pid = {131, 88, 100, 0, 0};
  CHECK_THROWS_WITH_AS(glass::scene::decodeErlangTerm(pid), doctest::Contains("tag 88"), glass::scene::ErlangTermError);
  // A list that claims four billion elements allocates nothing.
  const std::vector<std::uint8_t> huge = {131, 108, 255, 255, 255, 255, 106};
  CHECK_THROWS_WITH_AS(glass::scene::decodeErlangTerm(huge), doctest::Contains("more than the bytes left"),
                       glass::scene::ErlangTermError);
  // Nesting beyond the limit: [[[[...]]]].
  std::vector<std::uint8_t> deep = {131};
  for (int i = 0; i < 300; ++i) deep.insert(deep.end(), {108, 0, 0, 0, 1});
  deep.push_back(106);
  for (int i = 0; i < 300; ++i) deep.push_back(106);
  CHECK_THROWS_WITH_AS(glass::scene::decodeErlangTerm(deep), doctest::Contains("nest"), glass::scene::ErlangTermError);
  // A compressed term whose zlib stream is cut short.
  const std::vector<std::uint8_t> packed = bytesOf("shapes_compressed.term");
  CHECK_THROWS_WITH_AS(glass::scene::decodeErlangTerm(std::span(packed).first(packed.size() - 10)),
                       doctest::Contains("compressed term"), glass::scene::ErlangTermError);
}

TEST_CASE("Wings files: a cube with every edge hard, texture coordinates and materials") {
  const WingsFile file = glass::scene::readWingsFile(dataPath("cube_all_hard.wings"));
  REQUIRE(file.objects.size() == 1);
  REQUIRE(file.materials.size() == 2);
  CHECK(file.materials[0].name == "wood");
  CHECK(file.materials[1].name == "paint");
  CHECK(file.materials[1].diffuse[0] == doctest::Approx(0.75));
  CHECK(file.materials[1].shininess == doctest::Approx(64.0));
  const auto &cube = file.objects[0];
  CHECK(cube.name == "Cube");
  CHECK(cube.shape.vertices.size() == 8);
  REQUIRE(cube.shape.faces.size() == 6);
  CHECK(cube.shape.markedEdges.size() == 12);
  CHECK(signedVolume(cube.shape) == doctest::Approx(6.0));
  for (const auto &face : cube.shape.faces) {
    REQUIRE(face.vertices.size() == 4);
    REQUIRE(face.uvs.size() == 4);
    // The generator's texture coordinates: (x, -z) on the top face, painted; (x, y) in front.
    glm::dvec3 normal = glm::cross(cube.shape.vertices[face.vertices[1]] - cube.shape.vertices[face.vertices[0]],
                                   cube.shape.vertices[face.vertices[2]] - cube.shape.vertices[face.vertices[0]]);
    for (std::size_t k = 0; k < 4; ++k) {
      const glm::dvec3 &p = cube.shape.vertices[face.vertices[k]];
      if (normal.y > 0.5) CHECK(face.uvs[k] == glm::dvec2(p.x, -p.z));
      if (normal.z > 0.5) CHECK(face.uvs[k] == glm::dvec2(p.x, p.y));
    }
    CHECK(face.material == (normal.y > 0.5 ? 1 : 0));
  }
}

TEST_CASE("Wings files: objects without texture coordinates, several objects, names of any kind") {
  const WingsFile plain = glass::scene::readWingsFile(dataPath("cube_no_uvs.wings"));
  REQUIRE(plain.objects.size() == 1);
  CHECK(plain.materials.empty());
  for (const auto &face : plain.objects[0].shape.faces) {
    CHECK(face.uvs.empty());
    CHECK(face.material == -1);
  }
  CHECK(plain.objects[0].shape.markedEdges.empty());
  const WingsFile two = glass::scene::readWingsFile(dataPath("two_objects.wings"));
  REQUIRE(two.objects.size() == 2);
  CHECK(two.objects[0].name == "First");
  CHECK(two.objects[1].name == "C\xC3\xBC\xCE\xB1"); // [16#43, 16#FC, 16#3B1] in UTF-8
  CHECK(two.objects[1].shape.vertices[0].x == 3.0);
  CHECK(signedVolume(two.objects[1].shape) == doctest::Approx(6.0));
  const WingsFile block = glass::scene::readWingsFile(dataPath("block.wings"));
  REQUIRE(block.objects.size() == 1);
  CHECK(block.objects[0].shape.faces.size() == 24);
  CHECK(block.objects[0].shape.vertices.size() == 26);
  // The top ring, the flat edges inside the top (marked, but nothing to round), the upright.
  CHECK(block.objects[0].shape.markedEdges.size() == 14);
}

TEST_CASE("Wings files: a file saved by Wings3D") {
  const WingsFile file = glass::scene::readWingsFile(dataPath("wings3d_axes.wings"));
  REQUIRE(file.objects.size() == 1);
  const auto &axes = file.objects[0];
  CHECK(axes.name == "Cube1");
  CHECK(axes.shape.faces.size() == 30);
  CHECK(axes.shape.markedEdges.size() == 12);
  REQUIRE(file.materials.size() == 6);
  for (const auto &face : axes.shape.faces) CHECK(face.material >= 0);
  // Wings' faces are counter-clockwise seen from outside: the volume comes out positive.
  CHECK(signedVolume(axes.shape) > 0.0);

  // The cube of Wings3D's material icon: [-1, 1]^3, each face cut 14 x 14, the 12 x 14 edges
  // along the cube's edges hard; two materials, the faces in the second (its `opengl` diffuse
  // colour), edges with vertex colours (color_lt, color_rt), which are read past.
  const WingsFile boxFile = glass::scene::readWingsFile(dataPath("wings3d_material_box.wings"));
  REQUIRE(boxFile.objects.size() == 1);
  const auto &box = boxFile.objects[0].shape;
  CHECK(box.vertices.size() == 6 * 14 * 14 + 2);
  CHECK(box.faces.size() == 6 * 14 * 14);
  CHECK(box.markedEdges.size() == 12 * 14);
  REQUIRE(boxFile.materials.size() == 2);
  CHECK(boxFile.materials[1].name == "default3");
  CHECK(boxFile.materials[1].diffuse[0] == doctest::Approx(0.78985).epsilon(1e-4));
  for (const auto &face : box.faces) CHECK(face.material == 1);
  CHECK(signedVolume(box) / 6.0 == doctest::Approx(8.0).epsilon(1e-6));  // (six times the volume)
}

TEST_CASE("Wings files: broken and unsupported files name what is wrong") {
  CHECK(errorOf("version_3.wings").find("Wings format version 3 is not supported") != std::string::npos);
  CHECK(errorOf("not_a_tuple.wings").find("should be {wings, Version, Contents}") != std::string::npos);
  CHECK(errorOf("face_out_of_range.wings").find("object 'Cube', edge 0: left face 99 is out of range (there are 6)") !=
        std::string::npos);
  CHECK(errorOf("short_vertex.wings").find("object 'Cube', vertex 0 has no position") != std::string::npos);
  CHECK(errorOf("hard_edge_out_of_range.wings").find("object 'Cube', the hard edge list: edge 1000 is out of range") !=
        std::string::npos);
  CHECK(errorOf("no_edge_record.wings").find("object 'Cube', edge 0 has no {edge,") != std::string::npos);
  CHECK(errorOf("bad_shininess.wings").find("material 'shiny', shininess should be a number from 0 to 1") !=
        std::string::npos);
  CHECK(errorOf("missing.wings").find("missing.wings: cannot open the file") != std::string::npos);
  // Every message starts with the file's name.
  CHECK(errorOf("version_3.wings").rfind(dataPath("version_3.wings") + ": ", 0) == 0);

  const std::vector<std::uint8_t> good = bytesOf("block.wings");
  CHECK(parseError(std::span(good).first(10)).find("not a Wings file") != std::string::npos);
  CHECK(parseError(std::span(good).first(good.size() - 1)).find("(cut short)") != std::string::npos);
  std::vector<std::uint8_t> longer = good;
  longer.push_back(0);
  CHECK(parseError(longer).find("the header announces") != std::string::npos);
}

TEST_CASE("Wings files: any damage to a good file gives a message, never a crash") {
  const std::vector<std::uint8_t> good = bytesOf("block.wings");
  // Every cut, and every byte replaced by a few values, with the length fixed up so that the
  // damage reaches the term decoder and the object reader.
  for (std::size_t cut = 0; cut < good.size(); ++cut) {
    CAPTURE(cut);
    CHECK(!parseError(std::span(good).first(cut)).empty());
  }
  for (std::size_t at = 0; at < good.size(); ++at) {
    for (std::uint8_t value : {std::uint8_t{0}, std::uint8_t{1}, std::uint8_t{0x7f}, std::uint8_t{0xff}}) {
      std::vector<std::uint8_t> bad = good;
      bad[at] = value;
      try {
        glass::scene::parseWingsFile(bad);
      } catch (const WingsFileError &) {
      }
    }
  }
}
