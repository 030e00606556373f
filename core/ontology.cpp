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
                 const char* rellis, const char* kitti, uint16_t kitti_id) {
    auto& c = o.classes[uint8_t(r)];
    c.role = role_name(r);
    c.id = uint8_t(r);
    c.name = name;
    c.color = {cr, cg, cb};
    c.rugd = rugd;
    c.rellis = rellis;
    c.semantic_kitti = kitti;
    c.semantic_kitti_id = kitti_id;
  };
  set(Role::Background, "background", 0, 0, 0, "sky", "sky", "unlabeled", 0);
  set(Role::Ground, "ground", 108, 64, 20, "dirt", "dirt", "terrain", 72);
  set(Role::Trail, "trail", 255, 255, 0, "gravel", "mud", "other-ground", 49);
  set(Role::TreeTrunk, "tree_trunk", 102, 51, 0, "tree", "tree", "trunk", 71);
  set(Role::TreeCanopy, "tree_canopy", 0, 153, 0, "tree", "tree", "vegetation", 70);
  set(Role::DeadTree, "dead_tree", 153, 153, 153, "tree", "tree", "trunk", 71);
  set(Role::Stump, "stump", 204, 102, 0, "log", "log", "trunk", 71);
  set(Role::GroundVegetation, "ground_vegetation", 102, 255, 102, "grass", "grass", "terrain", 72);
  set(Role::Shrub, "shrub", 255, 153, 204, "bush", "bush", "vegetation", 70);
  set(Role::Obstacle, "obstacle", 153, 204, 255, "rock", "rubble", "other-object", 99);
  return o;
}

}  // namespace silva
