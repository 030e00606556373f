#include "core/ontology.hpp"

namespace silva {

namespace {
constexpr const char* kRoleNames[kRoleCount] = {
    "background", "ground", "trail", "tree_trunk", "tree_canopy",
    "dead_tree", "stump", "ground_vegetation", "shrub", "obstacle"};
}  // namespace

const char* role_name(Role r) { return kRoleNames[uint8_t(r)]; }

bool parse_role(const std::string& name, Role& out) {
  for (int i = 0; i < kRoleCount; ++i)
    if (name == kRoleNames[i]) {
      out = Role(i);
      return true;
    }
  return false;
}

bool role_has_instances(Role r) {
  switch (r) {
    case Role::TreeTrunk: case Role::DeadTree:
    case Role::Stump: case Role::Shrub: case Role::Obstacle:
      return true;
    default:
      return false;
  }
}

Ontology default_ontology() {
  Ontology o;
  auto set = [&](Role r, const char* name, uint8_t cr, uint8_t cg, uint8_t cb, const char* rugd,
                 const char* rellis) {
    auto& c = o.classes[uint8_t(r)];
    c.role = role_name(r);
    c.id = uint8_t(r);
    c.name = name;
    c.color = {cr, cg, cb};
    c.rugd = rugd;
    c.rellis = rellis;
  };
  set(Role::Background, "background", 0, 0, 0, "sky", "sky");
  set(Role::Ground, "ground", 108, 64, 20, "dirt", "dirt");
  set(Role::Trail, "trail", 255, 255, 0, "gravel", "mud");
  set(Role::TreeTrunk, "tree_trunk", 102, 51, 0, "tree", "tree");
  set(Role::TreeCanopy, "tree_canopy", 0, 153, 0, "tree", "tree");
  set(Role::DeadTree, "dead_tree", 153, 153, 153, "tree", "tree");
  set(Role::Stump, "stump", 204, 102, 0, "log", "log");
  set(Role::GroundVegetation, "ground_vegetation", 102, 255, 102, "grass", "grass");
  set(Role::Shrub, "shrub", 255, 153, 204, "bush", "bush");
  set(Role::Obstacle, "obstacle", 153, 204, 255, "rock", "rubble");
  return o;
}

}  // namespace silva
