#include "world/class_mix.hpp"

#include <algorithm>

namespace silva::world {

using assets::AssetKind;

ClassMix class_mix(double density_percent, bool ground, const ForestType& forest, Season season) {
  const double d = density_percent / 100.0;
  ClassMix m{};
  m[size_t(PointClass::Conifer)] = forest.conifer_share * d;
  m[size_t(PointClass::Broadleaf)] = (1.0 - forest.conifer_share) * d;
  m[size_t(PointClass::DeadTree)] = 0.1 * d;
  m[size_t(PointClass::Stump)] = 0.1 * d;
  m[size_t(PointClass::Shrub)] = (0.04 + 0.4 * d) * forest.shrub_scale;
  m[size_t(PointClass::Rock)] = 0.015;
  m[size_t(PointClass::Log)] = 0.005 + 0.05 * d;
  double used = 0;
  for (size_t k = 0; k < size_t(PointClass::Ground); ++k) used += m[k];
  m[size_t(PointClass::Ground)] = ground ? (1.0 - used) * forest.ground_share : 0.0;
  const double vernal = ground && vernal_season(season) ? std::max(0.0, forest.vernal_share - forest.ground_share) : 0.0;
  m[size_t(PointClass::Vernal)] = (1.0 - used) * vernal;
  m[size_t(PointClass::Nothing)] = 1.0 - used - m[size_t(PointClass::Ground)] - m[size_t(PointClass::Vernal)];
  return m;
}

PointClass pick_class(const ClassMix& mix, double u) {
  double acc = 0;
  for (size_t k = 0; k + 1 < mix.size(); ++k) {
    acc += mix[k];
    if (u < acc) return PointClass(k);
  }
  return PointClass::Nothing;
}

AssetKind kind_of(PointClass c) {
  switch (c) {
    case PointClass::Conifer: return AssetKind::ConiferTree;
    case PointClass::Broadleaf: return AssetKind::BroadleafTree;
    case PointClass::DeadTree: return AssetKind::DeadTree;
    case PointClass::Stump: return AssetKind::Stump;
    case PointClass::Shrub: return AssetKind::Shrub;
    case PointClass::Rock: return AssetKind::Rock;
    case PointClass::Log: return AssetKind::Log;
    default: return AssetKind::Count;
  }
}

uint8_t kind_rank(AssetKind k) {
  switch (k) {
    case AssetKind::ConiferTree:
    case AssetKind::BroadleafTree: return 0;
    case AssetKind::DeadTree: return 1;
    case AssetKind::Rock: return 2;
    case AssetKind::Log: return 3;
    case AssetKind::Stump: return 4;
    case AssetKind::Shrub: return 5;
    default: return 6;
  }
}

std::array<float, 2> scale_range(AssetKind k) {
  switch (k) {
    case AssetKind::Rock:
    case AssetKind::Shrub:
    case AssetKind::Grass:
    case AssetKind::Fern: return {0.7f, 1.3f};
    default: return {0.8f, 1.2f};
  }
}

bool is_solid(AssetKind k) { return k != AssetKind::Grass && k != AssetKind::Fern && k != AssetKind::Count; }

}  // namespace silva::world
