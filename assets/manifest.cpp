#include "assets/manifest.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/input_limits.hpp"

namespace silva::assets {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "silva-asset-library";
constexpr int kVersion = 1;
constexpr const char* kShapeNames[] = {"none", "cylinder", "capsule", "box", "sphere"};

/// Every kind name, comma-separated (for error messages).
std::string kind_names() {
  std::string out;
  for (size_t k = 0; k < size_t(AssetKind::Count); ++k) out += std::string(k ? ", " : "") + kind_name(AssetKind(k));
  return out;
}

json vec_json(const Vec3f& v) { return {v.x(), v.y(), v.z()}; }

json proxy_json(const CollisionProxy& p) {
  json j = {{"shape", kShapeNames[int(p.shape)]}};
  switch (p.shape) {
    case CollisionProxy::Shape::None:
      break;
    case CollisionProxy::Shape::Cylinder:
    case CollisionProxy::Shape::Capsule:
      j["center"] = vec_json(p.center), j["axis"] = vec_json(p.axis), j["radius"] = p.radius, j["height"] = p.height;
      break;
    case CollisionProxy::Shape::Sphere:
      j["center"] = vec_json(p.center), j["radius"] = p.radius;
      break;
    case CollisionProxy::Shape::Box:
      j["center"] = vec_json(p.center), j["half_extents"] = vec_json(p.half_extents);
      break;
  }
  return j;
}

/// Validating reader of one JSON object; every error names the file and the key path.
class Reader {
 public:
  Reader(const std::filesystem::path& file, const json& obj, std::string where)
      : file_(file), obj_(obj), where_(std::move(where)) {
    if (!obj_.is_object()) fail("", "must be an object");
  }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_.string() + ": " + where_ + (key.empty() ? "" : "." + key) + " " + what);
  }
  const json& need(const char* key) const {
    auto it = obj_.find(key);
    if (it == obj_.end()) fail(key, "is missing");
    return *it;
  }
  bool has(const char* key) const { return obj_.contains(key); }
  std::string string(const char* key) const {
    const json& v = need(key);
    if (!v.is_string() || v.get<std::string>().empty()) fail(key, "must be a non-empty string");
    return v.get<std::string>();
  }
  float number(const char* key, float lo, float hi) const {
    const json& v = need(key);
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo || v.get<double>() > hi)
      fail(key, "must be a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v.get<float>();
  }
  Vec3f vec3(const char* key) const {
    const json& v = need(key);
    constexpr double kMax = limits::kMaxAssetCoordinate;
    if (!v.is_array() || v.size() != 3 || !std::all_of(v.begin(), v.end(), [](const json& e) {
          return e.is_number() && std::abs(e.get<double>()) <= kMax;
        }))
      fail(key, "must be an array of 3 numbers in [-" + std::to_string(int(kMax)) + ", " + std::to_string(int(kMax)) +
                    "] metres");
    return Vec3f(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
  }
  Role role(const json& v, const std::string& key) const {
    Role r;
    if (!v.is_string() || !parse_role(v.get<std::string>(), r))
      fail(key, "must be a class name (background, ground, trail, tree_trunk, tree_canopy, dead_tree, stump, "
                "ground_vegetation, shrub, obstacle)");
    return r;
  }
  const std::string& where() const { return where_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  const std::filesystem::path& file_;
  const json& obj_;
  std::string where_;
};

CollisionProxy read_proxy(const Reader& r) {
  CollisionProxy p;
  const std::string shape = r.string("shape");
  const auto* it = std::find(std::begin(kShapeNames), std::end(kShapeNames), shape);
  if (it == std::end(kShapeNames)) r.fail("shape", "must be one of none, cylinder, capsule, box, sphere");
  p.shape = CollisionProxy::Shape(it - std::begin(kShapeNames));
  if (p.shape == CollisionProxy::Shape::None) return p;
  p.center = r.vec3("center");
  constexpr float kSize = float(limits::kMaxProxySize);
  if (p.shape == CollisionProxy::Shape::Box) {
    p.half_extents = r.vec3("half_extents");
    if (p.half_extents.minCoeff() <= 0 || p.half_extents.maxCoeff() > kSize)
      r.fail("half_extents", "must be positive and at most " + std::to_string(int(kSize)) + " m");
    return p;
  }
  p.radius = r.number("radius", 1e-6f, kSize);
  if (p.shape == CollisionProxy::Shape::Sphere) return p;
  p.height = r.number("height", 0, kSize);
  p.axis = r.vec3("axis");
  if (std::abs(p.axis.norm() - 1.0f) > 1e-4f) r.fail("axis", "must be a unit vector");
  return p;
}

/// The generator, variant and seed of a generator entry.
ProceduralSource read_source(const Reader& r) {
  ProceduralSource s;
  s.generator = r.string("generator");
  const json& v = r.need("variant");
  if (!v.is_number_integer() || v.get<int64_t>() < 0 || v.get<int64_t>() > 999999)
    r.fail("variant", "must be an integer in [0, 999999]");
  s.variant = v.get<uint32_t>();
  const std::string seed = r.string("seed");
  char* end = nullptr;
  s.seed = std::strtoull(seed.c_str(), &end, 16);
  if (seed.rfind("0x", 0) != 0 || seed.size() < 3 || seed.size() > 18 || *end != '\0')
    r.fail("seed", "must be a hexadecimal string \"0x...\" of at most 16 digits");
  return s;
}

/// The file, axis and parts of a file entry.
void read_file_fields(const Reader& r, ManifestEntry& e) {
  e.file = r.string("file");
  if (std::filesystem::path(e.file).is_absolute()) r.fail("file", "must be relative to the manifest's folder");
  if (r.has("up_axis")) {
    const std::string up = r.string("up_axis");
    if (up != "y" && up != "z") r.fail("up_axis", "must be \"y\" or \"z\"");
    e.z_up = up == "z";
  }
  const json& parts = r.need("parts");
  if (!parts.is_object() || parts.empty()) r.fail("parts", "must be a non-empty object {material name: class}");
  for (const auto& [material, cls] : parts.items()) e.parts[material] = r.role(cls, "parts." + material);
}

ManifestEntry read_entry(const Reader& r) {
  ManifestEntry e;
  e.name = r.string("name");
  if (r.has("generator") == r.has("file")) r.fail("", "needs exactly one of \"file\" and \"generator\"");
  if (r.has("generator"))
    e.source = read_source(r);
  else
    read_file_fields(r, e);
  if (!parse_kind(r.string("kind"), e.kind)) r.fail("kind", "must be one of " + kind_names());
  e.role = r.role(r.need("class"), "class");
  e.proxy = read_proxy(Reader(r.file(), r.need("collision"), r.where() + ".collision"));
  const json& sizes = r.need("lod_screen_sizes");
  if (!sizes.is_array()) r.fail("lod_screen_sizes", "must be an array of numbers");
  for (const json& s : sizes) {
    if (!s.is_number() || !(s.get<double>() > 0 && s.get<double>() <= 1) ||
        (!e.lod_screen_sizes.empty() && s.get<float>() >= e.lod_screen_sizes.back()))
      r.fail("lod_screen_sizes", "must be descending numbers in (0, 1]");
    e.lod_screen_sizes.push_back(s.get<float>());
  }
  return e;
}

}  // namespace

ManifestEntry manifest_entry(const Asset& asset) {
  ManifestEntry e;
  e.name = asset.name;
  e.file = asset.file;
  e.kind = asset.kind;
  e.role = asset.role;
  e.proxy = asset.proxy;
  e.lod_screen_sizes = asset.lod_screen_sizes;
  if (asset.file.empty() && asset.source) {
    e.source = asset.source;
    return e;
  }
  for (const MeshPart& part : asset.lods().at(0).parts) {
    auto [it, inserted] = e.parts.try_emplace(material_name(part.material), part.role);
    if (!inserted && it->second != part.role)
      throw InputError("asset " + asset.name + ": material " + it->first + " is used with two classes");
  }
  return e;
}

std::string manifest_text(std::span<const ManifestEntry> entries) {
  json assets = json::array();
  for (const ManifestEntry& e : entries) {
    json entry = {{"name", e.name}};
    if (e.source) {
      char seed[24];
      std::snprintf(seed, sizeof seed, "0x%llx", static_cast<unsigned long long>(e.source->seed));
      entry["generator"] = e.source->generator, entry["variant"] = e.source->variant, entry["seed"] = seed;
    } else {
      json parts = json::object();
      for (const auto& [material, role] : e.parts) parts[material] = role_name(role);
      entry["file"] = e.file, entry["up_axis"] = e.z_up ? "z" : "y", entry["parts"] = parts;
    }
    entry["kind"] = kind_name(e.kind);
    entry["class"] = role_name(e.role);
    entry["collision"] = proxy_json(e.proxy);
    entry["lod_screen_sizes"] = e.lod_screen_sizes;
    assets.push_back(std::move(entry));
  }
  return json{{"format", kFormat}, {"version", kVersion}, {"assets", assets}}.dump(2) + "\n";
}

std::vector<ManifestEntry> read_manifest(const std::filesystem::path& path) {
  return parse_manifest(limits::read_input_file(path, "asset library manifest"), path);
}

std::vector<ManifestEntry> parse_manifest(const std::string& text, const std::filesystem::path& path) {
  limits::check_json_depth(text, path.string());
  json doc = json::parse(text, nullptr, false);
  if (doc.is_discarded()) throw InputError(path.string() + ": not valid JSON");
  const Reader top(path, doc, "library");
  if (!top.need("format").is_string() || top.need("format").get<std::string>() != kFormat)
    top.fail("format", std::string("must be \"") + kFormat + "\"");
  if (!top.need("version").is_number_integer() || top.need("version").get<int>() != kVersion)
    top.fail("version", "must be " + std::to_string(kVersion));
  const json& assets = top.need("assets");
  if (!assets.is_array() || assets.empty()) top.fail("assets", "must be a non-empty array");
  std::vector<ManifestEntry> out;
  std::set<std::string> names;
  for (size_t i = 0; i < assets.size(); ++i) {
    const Reader r(path, assets[i], "assets[" + std::to_string(i) + "]");
    out.push_back(read_entry(r));
    if (!names.insert(out.back().name).second) r.fail("name", "'" + out.back().name + "' is not unique");
  }
  return out;
}

}  // namespace silva::assets
