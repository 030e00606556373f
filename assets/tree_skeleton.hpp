#pragma once
/// @file Recursive branching skeletons (Weber-Penn style): each level of branches is described by
/// a few numbers (children per parent, length ratio, down/rotate angles, curvature, taper,
/// gravitropism, apical dominance) and the generator grows polylines with radii from them.
#include <vector>

#include "assets/mesh_builder.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// How the first-order branches' lengths vary with their height on the trunk (crown outline).
enum class CrownShape : uint8_t {
  Conical,      ///< Longest at the crown base, shrinking to the top (spruce, fir, larch).
  Spherical,    ///< Longest mid-crown (beech, oak).
  Flame,        ///< Longest at 70 % of the crown height (birch).
  Domed,        ///< High rounded crown: long branches up to near the top (old pine).
};

/// Growth numbers of one branch level (level 0 is the trunk): how a branch of this level grows
/// from its parent (length, angles, bending, taper) and how its own children sit along it.
struct LevelParams {
  int children = 0;          ///< Children grown along each branch of this level.
  int whorl = 1;             ///< Children per whorl (1 = alternate, rotated by `rotate`).
  float start = 0.1f;        ///< Fraction of this branch's length where its children begin.
  float length = 0.3f;       ///< Length / parent length (level 1: times the crown-shape ratio).
  float length_var = 0.1f;   ///< Relative random variation of the child length.
  float down = 60.0f;        ///< Angle to the parent's direction for a fork at the parent's base (deg).
  float down_tip = 60.0f;    ///< Same angle for a fork at the parent's tip (deg).
  float down_var = 10.0f;    ///< Random variation of the down angle (deg).
  float rotate = 140.0f;     ///< Azimuth step between this branch's successive children or whorls (deg).
  float curve = 0.0f;        ///< Total bend in the branch's own plane over its length (deg; + = up).
  float curve_var = 10.0f;   ///< Random crookedness per segment (deg).
  float tropism = 0.0f;      ///< Bend towards -z per metre of the branch (droop; < 0 bends up).
  float apical = 0.3f;       ///< Apical dominance (level >= 2): a fork at the parent's tip is this much shorter.
  float tip_radius = 0.2f;   ///< Radius at the tip / radius at the base.
  int segments = 5;          ///< Polyline segments of each branch of this level.
};

/// Everything the skeleton generator needs for one tree.
struct SkeletonParams {
  float height = 20.0f;      ///< Trunk length (m).
  float base_radius = 0.3f;  ///< Trunk radius at the ground (m).
  CrownShape shape = CrownShape::Conical;  ///< Outline of the first-order branch lengths.
  float radius_power = 1.3f; ///< Child radius = parent radius there * (child length / parent length)^power.
  std::vector<LevelParams> levels;  ///< levels[0] is the trunk; a tree has levels.size() branch orders.
};

/// One grown branch: a polyline with radii, and where it sits on its parent.
struct Branch {
  std::vector<TubeNode> nodes;  ///< Centre line from base to tip, radius non-increasing.
  int parent = -1;              ///< Index of the parent branch (-1 for the trunk).
  int level = 0;                ///< Branch order (0 = trunk).
  float length = 0;             ///< Length along the polyline (m).
  float parent_t = 0;           ///< Fraction of the parent's length where it forks off.
};

/// A whole tree: branches in growth order (the trunk first, every parent before its children).
struct Skeleton {
  std::vector<Branch> branches;  ///< All branches.
  /// Number of branches of order `level`.
  int count(int level) const;
};

/// Grows the skeleton of one tree from its parameters; every random choice comes from `rng`.
Skeleton grow_skeleton(const SkeletonParams& p, Rng& rng);

/// Point and radius at fraction t in [0, 1] of a branch's length.
TubeNode point_along(const Branch& b, float t);

}  // namespace silva::assets
