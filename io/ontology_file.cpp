#include "io/ontology_file.hpp"

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/json_read.hpp"

namespace silva::io {

Ontology parse_ontology(const std::string& text, const std::string& source) {
  const nlohmann::json j = parse_json_text(text, source);
  const nlohmann::json& classes = json_member(j, "classes", source);
  if (!classes.is_array()) throw InputError(source + ": 'classes' must be a list of class objects");
  Ontology o;
  bool seen[kRoleCount] = {};
  for (size_t k = 0; k < classes.size(); ++k) {
    const std::string where = source + ": classes[" + std::to_string(k) + "]";
    const nlohmann::json& e = classes[k];
    const std::string role_text = json_string(e, "role", where);
    Role role;
    if (!parse_role(role_text, role)) {
      std::string allowed;
      for (int r = 0; r < kRoleCount; ++r) allowed += std::string(r ? ", " : "") + role_name(Role(r));
      throw InputError(where + ": unknown role \"" + role_text + "\"; allowed: " + allowed);
    }
    if (seen[uint8_t(role)]) throw InputError(where + ": role \"" + role_text + "\" appears more than once");
    seen[uint8_t(role)] = true;
    OntologyClass& c = o.classes[uint8_t(role)];
    c.role = role_text;
    c.id = uint8_t(json_int(e, "id", 0, 255, where));
    c.name = json_string(e, "name", where);
    const nlohmann::json& color = json_member(e, "color", where);
    if (!color.is_array() || color.size() != 3)
      throw InputError(where + ": 'color' must be [r, g, b] with integers 0..255, got " + limits::quoted_prefix(color.dump()));
    for (int a = 0; a < 3; ++a) {
      if (!color[a].is_number_integer() || color[a].get<long long>() < 0 || color[a].get<long long>() > 255)
        throw InputError(where + ": 'color' must be [r, g, b] with integers 0..255, got " + limits::quoted_prefix(color.dump()));
      c.color[a] = uint8_t(color[a].get<int>());
    }
    c.rugd = json_string(e, "rugd", where);
    c.rellis = json_string(e, "rellis", where);
    if (e.contains("semantic_kitti")) {
      c.semantic_kitti = json_string(e, "semantic_kitti", where);
      c.semantic_kitti_id = uint16_t(json_int(e, "semantic_kitti_id", 0, 65535, where));
    }
  }
  for (int r = 0; r < kRoleCount; ++r)
    if (!seen[r])
      throw InputError(source + ": role \"" + role_name(Role(r)) + "\" is missing; all ten roles must be listed once");
  return o;
}

Ontology load_ontology(const std::filesystem::path& path) {
  return parse_ontology(read_text_file(path), path.string());
}

std::string ontology_json(const Ontology& ontology) {
  std::string out = "{\n  \"classes\": [\n";
  for (int r = 0; r < kRoleCount; ++r) {
    const OntologyClass& c = ontology.classes[r];
    nlohmann::ordered_json e;
    e["role"] = c.role;
    e["id"] = c.id;
    e["name"] = c.name;
    e["color"] = {c.color[0], c.color[1], c.color[2]};
    e["rugd"] = c.rugd;
    e["rellis"] = c.rellis;
    if (!c.semantic_kitti.empty()) {
      e["semantic_kitti"] = c.semantic_kitti;
      e["semantic_kitti_id"] = c.semantic_kitti_id;
    }
    out += "    " + e.dump() + (r + 1 < kRoleCount ? ",\n" : "\n");
  }
  return out + "  ]\n}\n";
}

}  // namespace silva::io
