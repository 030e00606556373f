#include "assets/gltf_triangles.hpp"

#include <array>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace silva::assets {

namespace {

/// The JSON text of a glTF file: a .glb's first chunk (the container is checked before this runs),
/// else the whole file; "" when it is neither.
std::string gltf_json_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::array<char, 20> head{};
  if (in.read(head.data(), head.size()) && std::string_view(head.data(), 4) == "glTF") {
    uint32_t length = 0;
    std::memcpy(&length, &head[12], 4);  // glTF is little-endian, as every machine Silva builds for
    std::string json(length, '\0');
    return in.read(json.data(), std::streamsize(length)) ? json : std::string();
  }
  if (file.extension() != ".gltf") return {};
  in.clear();
  in.seekg(0);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// accessors[index].count, or 0 when the file does not give one.
uint64_t accessor_count(const nlohmann::json& gltf, const nlohmann::json& index) {
  if (!index.is_number_unsigned() || !gltf.contains("accessors") || !gltf["accessors"].is_array()) return 0;
  const nlohmann::json& accessors = gltf["accessors"];
  const uint64_t i = index.get<uint64_t>();
  if (i >= accessors.size() || !accessors[i].is_object()) return 0;
  const auto count = accessors[i].find("count");
  return count != accessors[i].end() && count->is_number_unsigned() ? count->get<uint64_t>() : 0;
}

/// The triangles one primitive declares (see gltf_declared_triangles).
uint64_t primitive_triangles(const nlohmann::json& gltf, const nlohmann::json& primitive) {
  if (!primitive.is_object()) return 0;
  const auto mode_at = primitive.find("mode");
  const int64_t mode = mode_at != primitive.end() && mode_at->is_number_integer() ? mode_at->get<int64_t>() : 4;
  uint64_t count = 0;
  if (primitive.contains("indices")) {
    count = accessor_count(gltf, primitive["indices"]);
  } else if (primitive.contains("attributes") && primitive["attributes"].is_object() &&
             primitive["attributes"].contains("POSITION")) {
    count = accessor_count(gltf, primitive["attributes"]["POSITION"]);
  }
  if (mode == 4) return count / 3;
  if (mode == 5 || mode == 6) return count >= 3 ? count - 2 : 0;
  return 0;  // points and lines carry no surface
}

}  // namespace

std::optional<uint64_t> gltf_declared_triangles(const std::filesystem::path& file) {
  const std::string text = gltf_json_text(file);
  if (text.empty()) return std::nullopt;
  const nlohmann::json gltf = nlohmann::json::parse(text, nullptr, false);
  if (gltf.is_discarded() || !gltf.is_object() || !gltf.contains("meshes") || !gltf["meshes"].is_array())
    return std::nullopt;
  uint64_t triangles = 0;
  for (const nlohmann::json& mesh : gltf["meshes"]) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (const nlohmann::json& primitive : mesh["primitives"]) triangles += primitive_triangles(gltf, primitive);
  }
  return triangles;
}

}  // namespace silva::assets
