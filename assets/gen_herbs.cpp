// Forest herbs: patches of stems on narrow stalk cards carrying flat leaf cards (wood sorrel, woodruff, nettle,
// wood anemone with a flower card on each flowering stem).
#include <cmath>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include "assets/generators.hpp"
#include "assets/shrub_parts.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

namespace {

/// Width of a stalk card, metres (its mask's line is a third to a quarter of it: a 1-1.5 mm stem).
constexpr float kStalkCardWidth = 0.004f;
/// Size of a stem's top leaf level relative to the ones below, when it has several.
constexpr float kTopLevelScale = 0.7f;

/// How one herb species grows in its patch.
struct HerbPatch {
  float height[2];                               ///< Range of the tallest stem's height, metres.
  float spread[2];                               ///< Range of the patch radius, metres.
  int min_stems, extra_stems;                    ///< Stems: min_stems + 0..extra_stems.
  float lean[2];                                 ///< Range of a stem's lean, as a share of its height.
  int levels[2];                                 ///< Range of leaf levels per stem (the top one at its tip).
  float level_step;                              ///< Step between a stem's leaf levels, as a share of its height.
  float span[2];                                 ///< Range of a leaf card's nominal leaf span, metres.
  float fill;                                    ///< Share of its card's side a leaf spans.
  float tilt;                                    ///< How far leaf cards tilt from facing up (add_leaf_card).
  std::shared_ptr<const AlphaMask> (*leaf_mask)();  ///< Mask of the leaf cards.
  Material material = Material::Herb;            ///< Material of the stalks and leaves.
  float top_gap = 0.0f;                          ///< Share of the stem above its highest leaf level (a flower stalk).
  std::shared_ptr<const AlphaMask> (*flower_mask)() = nullptr;  ///< Mask of the flower cards (null: no flowers).
  float flower_span[2] = {0.0f, 0.0f};          ///< Range of a flower card's nominal flower span, metres.
  float flower_share = 0.0f;                     ///< Share of stems that flower.
};

/// Share of its card's side a flower spans (the flower masks reach 0.46 from the centre).
constexpr float kFlowerFill = 0.92f;

/// How far flower cards tilt from facing up.
constexpr float kFlowerTilt = 0.35f;

/// A patch of `look`'s stems, each a stalk card with leaf cards at its levels, all of `look`'s material.
GeneratedAsset generate_herb_patch(Rng& rng, const HerbPatch& look) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(look.height[0], look.height[1]);  // the tallest stem
  const float spread = rng.range(look.spread[0], look.spread[1]);  // patch radius
  const int count = look.min_stems + int(rng.below(uint32_t(look.extra_stems + 1)));
  std::vector<std::pair<Vec3f, Vec3f>> stalks;  // base, top
  for (int i = 0; i < count; ++i) {
    const float az = rng.range(0.0f, 2.0f * kPi);
    const Vec3f base = spread * std::sqrt(rng.uniform()) * horizontal(az) - Vec3f(0, 0, 0.005f);
    const float h = height * rng.range(0.55f, 1.0f), lean = h * rng.range(look.lean[0], look.lean[1]);
    stalks.emplace_back(base, base + Vec3f(0, 0, h) + lean * horizontal(az + rng.range(-0.6f, 0.6f)));
  }
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, look.material, herb_stalk_mask(), true);
  for (const auto& [base, top] : stalks)
    add_card(b, 0.5f * (base + top), 0.5f * kStalkCardWidth * horizontal(rng.range(0.0f, 2.0f * kPi)), 0.5f * (top - base));
  b.begin_part(Role::GroundVegetation, look.material, look.leaf_mask(), true);
  const int extra_levels = look.levels[1] - look.levels[0];  // a fixed count (wood sorrel) draws nothing
  for (const auto& [base, top] : stalks) {  // leaves spread flat at the stem's levels, tilted a little
    const int levels = look.levels[0] + (extra_levels > 0 ? int(rng.below(uint32_t(extra_levels + 1))) : 0);
    for (int k = 0; k < levels; ++k) {
      const float below_top = look.top_gap + look.level_step * float(levels - 1 - k);  // share of the stem below its top
      const float scale = levels > 1 && k == levels - 1 ? kTopLevelScale : 1.0f;
      const float across = scale * rng.range(look.span[0], look.span[1]);
      add_leaf_card(b, rng, top - below_top * (top - base), Vec3f::UnitZ(), look.tilt, 0.5f * across / look.fill);
    }
  }
  if (look.flower_mask) {  // one flower at the top of each flowering stem, facing up
    b.begin_part(Role::GroundVegetation, Material::Petals, look.flower_mask(), true);
    for (const auto& stalk : stalks) {
      if (rng.uniform() >= look.flower_share) continue;
      const float across = rng.range(look.flower_span[0], look.flower_span[1]);
      add_leaf_card(b, rng, stalk.second, Vec3f::UnitZ(), kFlowerTilt, 0.5f * across / kFlowerFill);
    }
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace

GeneratedAsset generate_wood_sorrel(Rng& rng) {
  static const HerbPatch look{{0.05f, 0.13f}, {0.12f, 0.32f}, kMinWoodSorrelLeaves, 50, {0.05f, 0.4f}, {1, 1}, 0.2f,
                              {kWoodSorrelLeafSpan[0], kWoodSorrelLeafSpan[1]}, kWoodSorrelLeafFill, 0.35f,
                              wood_sorrel_leaf_mask};
  return generate_herb_patch(rng, look);
}

GeneratedAsset generate_woodruff(Rng& rng) {
  static const HerbPatch look{{0.12f, 0.28f}, {0.15f, 0.4f}, kMinWoodruffStems, 20, {0.03f, 0.25f},
                              {kWoodruffLevels[0], kWoodruffLevels[1]}, 0.2f, {kWoodruffWhorlSpan[0], kWoodruffWhorlSpan[1]},
                              kWoodruffWhorlFill, 0.25f, woodruff_whorl_mask};
  return generate_herb_patch(rng, look);
}

GeneratedAsset generate_wood_anemone(Rng& rng) {  // one leaf whorl below each flower
  static const HerbPatch look{.height = {0.1f, 0.25f}, .spread = {0.2f, 0.5f}, .min_stems = kMinWoodAnemoneStems,
                              .extra_stems = 30, .lean = {0.02f, 0.15f}, .levels = {1, 1}, .level_step = 0.0f,
                              .span = {kWoodAnemoneWhorlSpan[0], kWoodAnemoneWhorlSpan[1]}, .fill = kWoodAnemoneWhorlFill,
                              .tilt = 0.3f, .leaf_mask = wood_anemone_whorl_mask, .material = Material::Herb,
                              .top_gap = kWoodAnemoneFlowerStalk, .flower_mask = wood_anemone_flower_mask,
                              .flower_span = {kWoodAnemoneFlowerSpan[0], kWoodAnemoneFlowerSpan[1]},
                              .flower_share = kWoodAnemoneFlowering};
  return generate_herb_patch(rng, look);
}

GeneratedAsset generate_nettle(Rng& rng) {  // leaf pairs droop; the fern's material dies back in winter
  static const HerbPatch look{{0.5f, 1.1f}, {0.25f, 0.6f}, kMinNettleStems, 16, {0.02f, 0.12f},
                              {kNettleLevels[0], kNettleLevels[1]}, 0.1f, {kNettlePairSpan[0], kNettlePairSpan[1]},
                              kNettlePairFill, 0.6f, nettle_pair_mask, Material::Fern};
  return generate_herb_patch(rng, look);
}

GeneratedAsset generate_young_nettle(Rng& rng) {  // shoots of the same clonal spread, leaves crowded at their tops
  static const HerbPatch look{{0.18f, 0.35f}, {0.25f, 0.6f}, kMinNettleStems, 16, {0.02f, 0.12f},
                              {kYoungNettleLevels[0], kYoungNettleLevels[1]}, 0.07f,
                              {kYoungNettlePairSpan[0], kYoungNettlePairSpan[1]}, kNettlePairFill, 0.5f, nettle_pair_mask,
                              Material::Fern};
  return generate_herb_patch(rng, look);
}

}  // namespace silva::assets
