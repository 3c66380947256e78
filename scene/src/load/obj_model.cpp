#include "obj_model.h"

#include "gl_api.h"
#include "image_file.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace glass::scene {

namespace {

std::array<float, 4> rgb1(const tinyobj::real_t c[3]) {
  return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]), 1.0f};
}

// The first fault that tinyobjloader's warnings name, in glass's words: a material library or
// material that is missing, a face with fewer than three corners. (Its other warnings, such as
// an MTL giving both d and Tr, leave a usable model.) Empty when there is none.
std::string faultInWarnings(const std::string &warnings) {
  // tinyobjloader names the file or material between "[ " and " ]".
  const auto named = [](const std::string &line) {
    std::size_t open = line.find("[ "), close = line.find(" ]");
    if (open == std::string::npos || close == std::string::npos || close < open + 2) return std::string();
    std::string name = line.substr(open + 2, close - open - 2);
    if (name.size() >= 2 && name.front() == '\'' && name.back() == '\'') name = name.substr(1, name.size() - 2);
    return name;
  };
  std::size_t start = 0;
  while (start < warnings.size()) {
    std::size_t end = warnings.find('\n', start);
    if (end == std::string::npos) end = warnings.size();
    std::string line = warnings.substr(start, end - start);
    start = end + 1;
    if (line.find("Material file") != std::string::npos && line.find("not found") != std::string::npos) {
      return "its material library '" + named(line) + "' is not found next to it";
    }
    if (line.find("not found in .mtl") != std::string::npos) {
      return "material '" + named(line) + "' is not in its material library";
    }
    if (line.find("Degenerated face") != std::string::npos) return "a face has fewer than 3 corners";
    if (line.find("error state") != std::string::npos) return "its material library cannot be read";
  }
  return {};
}

// Every vertex, texture coordinate and normal index of a face (f), line (l) or point (p) must name
// an element the file has: 1 to the count, or -1 back to minus the count read so far. The indices
// are checked here as written, before tinyobjloader reads the file: it converts them to int
// without overflow checks (vertex 2147483648 would become a negative index) and reads the
// positions of the faces it triangulates without range checks.
bool checkFaceIndices(const std::string &path, std::string &reason) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return true;  // the real read reports it
  static const char *const kKindNames[3] = {"vertex", "texture coordinate", "normal"};
  std::uint64_t counts[3] = {0, 0, 0};  // v, vt, vn read so far
  struct Pending {                      // an absolute index, checked once the counts are known
    int kind;
    std::string written;
    std::uint64_t value;
  };
  std::vector<Pending> pending;
  const auto fail = [&](int kind, const std::string &written, std::uint64_t have) {
    reason = "a face names " + std::string(kKindNames[kind]) + " " + written + ", but the file has " +
             std::to_string(have) + " (OBJ counts from 1)";
    return false;
  };
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string keyword;
    if (!(words >> keyword)) continue;
    if (keyword == "v") ++counts[0];
    else if (keyword == "vt") ++counts[1];
    else if (keyword == "vn") ++counts[2];
    if (keyword != "f" && keyword != "l" && keyword != "p") continue;
    std::string corner;
    while (words >> corner) {
      std::size_t start = 0;
      for (int kind = 0; kind < 3 && start <= corner.size(); ++kind) {
        std::size_t slash = corner.find('/', start);
        if (slash == std::string::npos) slash = corner.size();
        const std::string written = corner.substr(start, slash - start);
        start = slash + 1;
        if (written.empty()) continue;  // v//vn: no texture coordinate
        const bool relative = written[0] == '-';
        const char *digits = written.c_str() + (relative || written[0] == '+' ? 1 : 0);
        std::uint64_t value = 0;
        const char *last = written.c_str() + written.size();
        const auto [end, error] = std::from_chars(digits, last, value);
        if (error == std::errc::result_out_of_range) value = UINT64_MAX;  // beyond any count
        else if (error != std::errc() || end != last) {
          reason = "a face corner '" + corner + "' is not a vertex index";
          return false;
        }
        if (relative) {  // -k: the k-th element before this line
          if (value == 0 || value > counts[kind]) return fail(kind, written, counts[kind]);
        } else {
          pending.push_back({kind, written, value});
        }
      }
    }
  }
  for (const Pending &p : pending)
    if (p.value == 0 || p.value > counts[p.kind]) return fail(p.kind, p.written, counts[p.kind]);
  return true;
}

} // namespace

bool loadObjModel(const std::string &path, Model &model, std::vector<TextureDefinition> &textures,
                  std::string &reason) {
  std::filesystem::path directory = std::filesystem::path(path).parent_path();
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = directory.string();
  tinyobj::ObjReader reader;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    reason = std::filesystem::exists(path, ec) ? "not a regular file" : "no such file";
    return false;
  }
  if (!checkFaceIndices(path, reason)) return false;
  if (!reader.ParseFromFile(path, config)) {
    reason = reader.Error().empty() ? "not a readable OBJ file" : reader.Error();
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == '\r')) reason.pop_back();
    return false;
  }
  // A missing MTL file or material is a missing file, an error as for textures.
  if (std::string fault = faultInWarnings(reader.Warning()); !fault.empty()) {
    reason = fault;
    return false;
  }
  const tinyobj::attrib_t &attrib = reader.GetAttrib();
  model.path = path;

  // Materials; a diffuse map becomes a texture with trilinear mipmapping.
  std::map<std::string, int> textureByPath;
  for (const tinyobj::material_t &m : reader.GetMaterials()) {
    ModelMaterial material;
    material.ambient = rgb1(m.ambient);
    material.diffuse = rgb1(m.diffuse);
    material.specular = rgb1(m.specular);
    material.emission = rgb1(m.emission);
    material.diffuse[3] = static_cast<float>(m.dissolve);
    // MTL's Ns runs to 1000; GL's shininess stops at 128.
    material.shininess = std::clamp(static_cast<float>(m.shininess), 0.0f, 128.0f);
    if (!m.diffuse_texname.empty()) {
      std::string texturePath = (directory / m.diffuse_texname).lexically_normal().string();
      auto found = textureByPath.find(texturePath);
      if (found != textureByPath.end()) {
        material.texture = found->second;
      } else {
        TextureDefinition texture;
        texture.name = std::filesystem::path(path).filename().string() + ":" + m.diffuse_texname;
        texture.path = texturePath;
        std::string why;
        if (!loadImageFile(texturePath, texture.image, why)) {
          reason = "material '" + m.name + "': cannot read texture '" + texturePath + "': " + why;
          return false;
        }
        texture.minFilter = GL_LINEAR_MIPMAP_LINEAR;
        texture.magFilter = GL_LINEAR;
        texture.wrapS = GL_REPEAT;
        texture.wrapT = GL_REPEAT;
        texture.mipmaps = true;
        material.texture = static_cast<int>(textures.size());
        textureByPath[texturePath] = material.texture;
        textures.push_back(std::move(texture));
      }
    }
    model.materials.push_back(material);
  }

  // Triangles, grouped by material so that the interpreter sets each material once.
  std::map<int, std::size_t> partByMaterial;
  bool anyNormals = !attrib.normals.empty();
  model.hasNormals = anyNormals;
  for (const tinyobj::shape_t &shape : reader.GetShapes()) {
    const tinyobj::mesh_t &mesh = shape.mesh;
    std::size_t offset = 0;
    for (std::size_t face = 0; face < mesh.num_face_vertices.size(); ++face) {
      std::size_t corners = mesh.num_face_vertices[face];
      if (corners != 3) { // triangulation leaves only triangles; skip lines and points
        offset += corners;
        continue;
      }
      int materialId = face < mesh.material_ids.size() ? mesh.material_ids[face] : -1;
      if (materialId >= static_cast<int>(model.materials.size())) materialId = -1;
      auto [it, inserted] = partByMaterial.try_emplace(materialId, model.parts.size());
      if (inserted) {
        model.parts.emplace_back();
        model.parts.back().material = materialId;
      }
      ModelPart &part = model.parts[it->second];
      float corner[3][3];
      bool haveNormals = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t &index = mesh.indices[offset + k];
        for (int c = 0; c < 3; ++c) {
          corner[k][c] = static_cast<float>(attrib.vertices[3 * static_cast<std::size_t>(index.vertex_index) + static_cast<std::size_t>(c)]);
          part.positions.push_back(corner[k][c]);
        }
        haveNormals = haveNormals && index.normal_index >= 0;
        if (index.texcoord_index >= 0) {
          part.texcoords.push_back(static_cast<float>(attrib.texcoords[2 * static_cast<std::size_t>(index.texcoord_index)]));
          part.texcoords.push_back(static_cast<float>(attrib.texcoords[2 * static_cast<std::size_t>(index.texcoord_index) + 1]));
        } else {
          part.texcoords.push_back(0.0f);
          part.texcoords.push_back(0.0f);
        }
      }
      if (haveNormals) {
        for (std::size_t k = 0; k < 3; ++k) {
          const tinyobj::index_t &index = mesh.indices[offset + k];
          for (int c = 0; c < 3; ++c) {
            part.normals.push_back(static_cast<float>(attrib.normals[3 * static_cast<std::size_t>(index.normal_index) + static_cast<std::size_t>(c)]));
          }
        }
      } else {
        // The face normal (b - a) x (c - a), counter-clockwise faces facing out as OBJ has them.
        float u[3], v[3], n[3];
        for (int c = 0; c < 3; ++c) {
          u[c] = corner[1][c] - corner[0][c];
          v[c] = corner[2][c] - corner[0][c];
        }
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (length > 0.0f) {
          for (float &x : n) x /= length;
        }
        for (int k = 0; k < 3; ++k) part.normals.insert(part.normals.end(), n, n + 3);
      }
      offset += corners;
    }
  }
  if (model.parts.empty()) {
    reason = "it has no faces";
    return false;
  }
  return true;
}

} // namespace glass::scene
