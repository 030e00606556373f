#include "assets/species.hpp"

#include "assets/foliage_sprays.hpp"

namespace silva::assets {

namespace {

/// The trunk: children (first-order branches) in whorls of `whorl` from `start`, azimuth step `rotate`.
LevelParams trunk(int children, int whorl, float start, float rotate, float crooked, float tip) {
  return {.children = children, .whorl = whorl, .start = start, .length = 1, .length_var = 0, .down = 0,
          .down_tip = 0, .down_var = 0, .rotate = rotate, .curve = 0, .curve_var = crooked, .tropism = 0,
          .apical = 0, .tip_radius = tip, .segments = 10};
}

/// Foliage cards on the twigs.
FoliageParams cards(MaskFamily family, Material m, CardStyle style, float half, float spacing,
                    float start, float droop, int level, int max_cards) {
  return {.mask = nullptr, .family = family, .material = m, .role = Role::TreeCanopy, .style = style, .half = half,
          .spacing = spacing, .start = start, .droop = droop, .level = level, .max_cards = max_cards};
}

}  // namespace

const Species& norway_spruce() {
  static const Species s{
      "norway_spruce", 22, 32, 1.0f, 1.0f / 110,
      {.shape = CrownShape::Conical, .radius_power = 0.9f,
       .levels = {trunk(90, 5, 0.08f, 37, 1.5f, 0.03f),
                  {.children = 16, .whorl = 2, .start = 0.1f, .length = 0.2f, .length_var = 0.15f, .down = 105,
                   .down_tip = 70, .down_var = 8, .rotate = 0, .curve = 30, .curve_var = 4, .tropism = 0.04f,
                   .apical = 0, .tip_radius = 0.08f, .segments = 4},
                  {.length = 0.32f, .length_var = 0.2f, .down = 70, .down_tip = 50, .down_var = 12, .curve_var = 6,
                   .tropism = 0.25f, .apical = 0.5f, .tip_radius = 0.3f, .segments = 2}}},
      {Material::BarkSpruce, Role::TreeTrunk, true,
       cards(spruce_spray, Material::NeedlesSpruce, CardStyle::Spray, 0.37f, 0.2f, 0.05f, 0.4f, 1, 4800)}};
  return s;
}

const Species& scots_pine() {
  static const Species s{
      "scots_pine", 18, 28, 1.0f, 1.0f / 100,
      {.shape = CrownShape::Domed, .radius_power = 0.9f,
       .levels = {trunk(36, 4, 0.55f, 40, 2.5f, 0.04f),
                  {.children = 9, .start = 0.3f, .length = 0.26f, .length_var = 0.3f, .down = 100, .down_tip = 60,
                   .down_var = 12, .rotate = 140, .curve = 20, .curve_var = 16, .tip_radius = 0.12f, .segments = 5},
                  {.length = 0.3f, .length_var = 0.3f, .down = 50, .down_tip = 40, .down_var = 15, .curve = 15,
                   .curve_var = 10, .tropism = -0.03f, .apical = 0.3f, .tip_radius = 0.3f, .segments = 2}}},
      {Material::BarkPine, Role::TreeTrunk, true,
       cards(pine_spray, Material::NeedlesPine, CardStyle::Cluster, 0.57f, 0.16f, 0.45f, 0.0f, 1, 4800)}};
  return s;
}

const Species& european_larch() {
  static const Species s{
      "european_larch", 20, 30, 1.0f, 1.0f / 105,
      {.shape = CrownShape::Conical, .radius_power = 0.9f,
       .levels = {trunk(60, 1, 0.15f, 140, 2.0f, 0.03f),
                  {.children = 12, .start = 0.15f, .length = 0.2f, .length_var = 0.2f, .down = 95, .down_tip = 65,
                   .down_var = 10, .rotate = 150, .curve = 15, .curve_var = 6, .tropism = 0.02f,
                   .tip_radius = 0.1f, .segments = 4},
                  {.length = 0.45f, .length_var = 0.2f, .down = 60, .down_tip = 50, .down_var = 15, .curve_var = 6,
                   .tropism = 0.35f, .apical = 0.4f, .tip_radius = 0.3f, .segments = 3}}},
      {Material::BarkLarch, Role::TreeTrunk, true,
       cards(larch_spray, Material::NeedlesLarch, CardStyle::Spray, 0.30f, 0.2f, 0.2f, 0.2f, 1, 4500)}};
  return s;
}

const Species& european_beech() {
  static const Species s{
      "european_beech", 22, 32, 0.75f, 1.0f / 80,
      {.shape = CrownShape::Spherical, .radius_power = 1.1f,
       .levels = {trunk(18, 1, 0.35f, 140, 3.0f, 0.2f),
                  {.children = 10, .start = 0.15f, .length = 0.42f, .length_var = 0.2f, .down = 60, .down_tip = 35,
                   .down_var = 10, .rotate = 140, .curve = -10, .curve_var = 6, .tip_radius = 0.15f, .segments = 5},
                  {.children = 7, .start = 0.2f, .length = 0.45f, .length_var = 0.2f, .down = 50, .down_tip = 40,
                   .down_var = 15, .rotate = 140, .curve_var = 8, .tropism = 0.02f, .apical = 0.4f,
                   .tip_radius = 0.25f, .segments = 3},
                  {.length = 0.5f, .length_var = 0.2f, .down = 45, .down_tip = 40, .down_var = 20, .curve_var = 10,
                   .tropism = 0.05f, .apical = 0.3f, .tip_radius = 0.4f, .segments = 2}}},
      {Material::BarkBeech, Role::TreeTrunk, true,
       cards(beech_spray, Material::LeavesBeech, CardStyle::Spray, 0.48f, 0.22f, 0.3f, 0.1f, 2, 5000)}};
  return s;
}

const Species& silver_birch() {
  static const Species s{
      "silver_birch", 15, 24, 0.85f, 1.0f / 110,
      {.shape = CrownShape::Flame, .radius_power = 1.0f,
       .levels = {trunk(26, 1, 0.3f, 140, 3.0f, 0.08f),
                  {.children = 14, .start = 0.15f, .length = 0.3f, .length_var = 0.2f, .down = 50, .down_tip = 30,
                   .down_var = 10, .rotate = 140, .curve = -25, .curve_var = 6, .tropism = 0.02f,
                   .tip_radius = 0.12f, .segments = 4},
                  {.length = 0.55f, .length_var = 0.2f, .down = 40, .down_tip = 30, .down_var = 15, .curve_var = 6,
                   .tropism = 0.4f, .apical = 0.3f, .tip_radius = 0.3f, .segments = 4}}},
      {Material::BarkBirch, Role::TreeTrunk, true,
       cards(birch_spray, Material::LeavesBirch, CardStyle::Spray, 0.28f, 0.2f, 0.1f, 0.5f, 2, 4000)}};
  return s;
}

const Species& common_oak() {
  static const Species s{
      "common_oak", 18, 26, 0.55f, 1.0f / 60,
      {.shape = CrownShape::Spherical, .radius_power = 1.15f,
       .levels = {trunk(9, 1, 0.35f, 140, 6.0f, 0.35f),
                  {.children = 8, .start = 0.15f, .length = 0.9f, .length_var = 0.2f, .down = 60, .down_tip = 35,
                   .down_var = 15, .rotate = 140, .curve = -10, .curve_var = 14, .tip_radius = 0.15f, .segments = 5},
                  {.children = 7, .start = 0.15f, .length = 0.45f, .length_var = 0.25f, .down = 55, .down_tip = 45,
                   .down_var = 20, .rotate = 140, .curve_var = 16, .tropism = 0.01f, .apical = 0.3f,
                   .tip_radius = 0.25f, .segments = 3},
                  {.length = 0.45f, .length_var = 0.25f, .down = 50, .down_tip = 50, .down_var = 25, .curve_var = 20,
                   .tropism = 0.02f, .apical = 0.3f, .tip_radius = 0.4f, .segments = 2}}},
      {Material::BarkOak, Role::TreeTrunk, true,
       cards(oak_spray, Material::LeavesOak, CardStyle::Cluster, 0.52f, 0.18f, 0.3f, 0.0f, 2, 4800)}};
  return s;
}

}  // namespace silva::assets
