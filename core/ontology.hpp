#pragma once
/// @file The ten semantic roles of the thesis (section 4.6.2) and the user-remappable ontology.
#include <array>
#include <cstdint>
#include <string>

namespace silva {

/// Fixed semantic roles; the numeric value is the default class id (CONTRACT.md ontology).
enum class Role : uint8_t {
  Background = 0,
  Ground = 1,
  Trail = 2,
  TreeTrunk = 3,
  TreeCanopy = 4,
  DeadTree = 5,
  Stump = 6,
  GroundVegetation = 7,
  Shrub = 8,
  Obstacle = 9,
};

/// Number of fixed roles.
inline constexpr int kRoleCount = 10;

/// One class of the ontology: what a role is written as.
struct OntologyClass {
  std::string role;                  ///< Fixed role name, e.g. "tree_trunk".
  uint8_t id = 0;                    ///< Class id written to semantic images (0..255).
  std::string name;                  ///< Human-readable name.
  std::array<uint8_t, 3> color{};    ///< RGB colour for semantic_color images.
  std::string rugd;                  ///< RUGD class mapping.
  std::string rellis;                ///< RELLIS-3D class mapping.
  std::string semantic_kitti;        ///< SemanticKITTI class name ("" = unmapped).
  uint16_t semantic_kitti_id = 0;    ///< SemanticKITTI raw label id (0 = unlabeled).
};

/// The ontology: one entry per role, indexed by Role's numeric value.
struct Ontology {
  std::array<OntologyClass, kRoleCount> classes;  ///< Indexed by uint8_t(Role).
  /// Class id for a role.
  uint8_t id(Role r) const { return classes[uint8_t(r)].id; }
  /// Colour for a role.
  const std::array<uint8_t, 3>& color(Role r) const { return classes[uint8_t(r)].color; }
};

/// The default ontology of CONTRACT.md (ids equal role values).
Ontology default_ontology();

/// Role name ("tree_trunk"), as used in ontology.json and the asset library.
const char* role_name(Role r);

/// Parses a role name; returns false if unknown.
bool parse_role(const std::string& name, Role& out);

/// True for roles whose pixels carry an instance index: trunks, dead trees, stumps, shrubs,
/// obstacles. Canopy pixels are labelled by class only (instance 0): an instance table entry has
/// one class, and a tree's instance is its trunk (CONTRACT.md: the tree node's class is tree_trunk).
bool role_has_instances(Role r);

}  // namespace silva
