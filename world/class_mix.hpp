#pragma once
/// @file What a placement grid point holds, by tree density (thesis 4.1.2 and 5.1: more trees
/// mean fewer ground-vegetation points; dead trees, stumps and logs scale with the trees;
/// shrubs fill under the canopy).
#include <array>
#include <cstdint>

#include "assets/library.hpp"
#include "world/forest_types.hpp"

namespace silva::world {

/// Classes a placement point can hold: one solid kind, ground vegetation, or nothing.
/// Vernal: ground vegetation of vernal herbs only, on floor that is bare the rest of the year.
enum class PointClass : uint8_t { Conifer, Broadleaf, DeadTree, Stump, Shrub, Rock, Log, Ground, Vernal, Nothing, Count };

/// Probability of each PointClass at one grid point; sums to 1.
using ClassMix = std::array<double, size_t(PointClass::Count)>;

/// The mix for `density_percent` (1..25: percent of points holding a tree) in forest type `forest`
/// (its conifer share of the trees, its shrub factor, its share of ground-vegetation points that are not
/// bare; in `season`s with vernal herbs, its larger vernal share, the difference as Vernal points); with ground =
/// false the ground-vegetation share holds nothing.
ClassMix class_mix(double density_percent, bool ground, const ForestType& forest = forest_types().front(),
                   Season season = Season::Summer);

/// Class of a point from a uniform draw u in [0, 1) (cumulative thresholds in enum order).
PointClass pick_class(const ClassMix& mix, double u);

/// Asset kind of a solid point class (not Ground/Vernal/Nothing).
assets::AssetKind kind_of(PointClass c);

/// Resolve priority rank of a kind: lower wins (trees, dead trees, rocks, logs, stumps, shrubs).
uint8_t kind_rank(assets::AssetKind k);

/// Scale range [lo, hi) drawn uniformly for a kind.
std::array<float, 2> scale_range(assets::AssetKind k);

/// Largest scale any kind can draw.
inline constexpr float kMaxScale = 1.3f;

/// True for kinds with a solid collision proxy that take part in overlap resolution.
bool is_solid(assets::AssetKind k);

}  // namespace silva::world
