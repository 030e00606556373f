#pragma once
/// @file The procedural asset generators, one per kind (one .cpp each). A generator draws every
/// choice from the stream it is given and returns the full-detail mesh (origin at the ground
/// contact point, Z up, metres), the class of the object node and the collision proxy.
#include "assets/library.hpp"
#include "assets/mesh_builder.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// A generated asset before LODs.
struct GeneratedAsset {
  Mesh mesh;              ///< Full-detail mesh with its parts.
  Role role;              ///< Class of the object node (the trunk for trees).
  CollisionProxy proxy;   ///< Solid proxy (shape None for ground vegetation).
};

/// Norway spruce grown by the branching generator (assets/species.hpp), sapling to mature (1-32 m).
GeneratedAsset generate_spruce(Rng& rng);
/// Scots pine, sapling to mature (1-28 m).
GeneratedAsset generate_pine(Rng& rng);
/// European larch, sapling to mature (1-30 m).
GeneratedAsset generate_larch(Rng& rng);
/// European beech, sapling to mature (1-32 m).
GeneratedAsset generate_beech(Rng& rng);
/// Silver birch, sapling to mature (1-24 m).
GeneratedAsset generate_birch(Rng& rng);
/// Pedunculate oak, sapling to mature (1-26 m).
GeneratedAsset generate_oak(Rng& rng);
/// Dead snag: 8-20 m grown trunk, branches mostly broken off short (splintered ends), most with a
/// snapped top (splinter and wood disc), 70 % with bare twig cards.
GeneratedAsset generate_dead_tree(Rng& rng);
/// Fallen dead tree lying along X (centred on the origin), 3.5-14 m, with its torn-up root plate
/// (soil disc and roots) at the -X end; obstacle role, capsule proxy along the trunk.
GeneratedAsset generate_fallen_tree(Rng& rng);
/// Stump: 0.3-0.9 m high, bark sides flaring into 3-6 buttress roots; a weathered sawn (slightly
/// tilted) or broken, splintered top.
GeneratedAsset generate_stump(Rng& rng);
/// Short grass clump: 0.1-0.35 m, 6-10 curved cards of dense blade tufts.
GeneratedAsset generate_grass(Rng& rng);
/// Tall grass clump: 0.35-0.8 m, curved tuft cards plus cards with seed-head stalks.
GeneratedAsset generate_tall_grass(Rng& rng);
/// Grass sward: a patch of kGrassSwardRadius of low, dense fine grass, kGrassSwardCardsPerSquareMetre
/// curved cards (at least kMinGrassSwardCards) of the sward mask, kGrassSwardHeight high.
GeneratedAsset generate_grass_sward(Rng& rng);
/// Range of a sward patch's radius, metres.
inline constexpr float kGrassSwardRadius[2] = {0.18f, 0.42f};
/// Range of a sward patch's card height, metres (a card 0.7-1 of it; its blades 0.45-1 of the card).
inline constexpr float kGrassSwardHeight[2] = {0.06f, 0.18f};
/// Width of a sward card, metres: its mask's blades are 1.9-2.8 mm wide (woodland grasses 1-4 mm).
inline constexpr float kGrassSwardCardWidth = 0.16f;
/// Sward cards per square metre of patch (each carries kGrassSwardBlades blades: ~5 700 per m^2).
inline constexpr float kGrassSwardCardsPerSquareMetre = 110.0f;
/// Fewest cards of a sward patch.
inline constexpr int kMinGrassSwardCards = 6;
/// Fern: a rosette of 5-12 arching pinnate fronds (bent strips of kFrondSegments quads), in three
/// size classes 0.18-0.4, 0.4-0.7 and 0.7-1.05 m high.
GeneratedAsset generate_fern(Rng& rng);
/// The same fern (the same draws) in spring: each frond unrolled for a share kYoungFrondOpen of its grown length,
/// standing steeply, its pinnae half spread (a strip of kYoungFrondSegments quads), the rest of it rolled up above
/// in a crozier kCrozierRadius in radius (a solid coil of kCrozierSegments tube sections); young light green
/// (SpringLeaves).
GeneratedAsset generate_young_fern(Rng& rng);
/// Range of the share of its grown length a young frond has unrolled (croziers just up to nearly open).
inline constexpr float kYoungFrondOpen[2] = {0.1f, 0.6f};
/// Quads along a young frond's unrolled blade.
inline constexpr int kYoungFrondSegments = 6;
/// Tube sections along a crozier's coil.
inline constexpr int kCrozierSegments = 8;
inline constexpr int kCrozierSides = 4;  ///< Sides around a crozier's coil.
/// A crozier coil's thickness (the tube's radius at its start) as a share of the coil's outer radius; it tapers to
/// 40 % at the tip (the rolled pinnae fill the coil).
inline constexpr float kCrozierThickness = 0.5f;
/// How far (radians) a young frond's unrolled part bends out from its steep start.
inline constexpr float kYoungFrondBend = 0.35f;
/// A crozier's outer radius per metre of grown frond (times 1.5 less the unrolled share), clamped to
/// kCrozierRadius (metres: coils 1.6-4 cm across, as a male fern's or bracken's).
inline constexpr float kCrozierRadiusPerLength = 0.04f;
inline constexpr float kCrozierRadius[2] = {0.008f, 0.02f};  ///< Range of a crozier's outer radius, metres.
/// Wood sorrel: a carpet patch of kMinWoodSorrelLeaves-80 trifoliate leaves spreading flat atop
/// 5-13 cm stalks, each leaf kWoodSorrelLeafSpan across (x 0.8-1.2); ground vegetation, grown as a fern-layer herb.
GeneratedAsset generate_wood_sorrel(Rng& rng);
/// Fewest leaves of a wood sorrel patch.
inline constexpr int kMinWoodSorrelLeaves = 30;
/// Range of a wood sorrel leaf's nominal span across its three leaflets, metres (Oxalis acetosella: 2-4.5 cm).
inline constexpr float kWoodSorrelLeafSpan[2] = {0.028f, 0.042f};
/// Share of its card's side a wood sorrel leaf spans (the mask's leaflets reach 0.43 from the centre).
inline constexpr float kWoodSorrelLeafFill = 0.86f;
/// Woodruff: a carpet patch of kMinWoodruffStems-36 upright stems 7-28 cm high, each with kWoodruffLevels whorls
/// of lanceolate leaves kWoodruffWhorlSpan across (the top whorl smaller); grown as a fern-layer herb.
GeneratedAsset generate_woodruff(Rng& rng);
/// Fewest stems of a woodruff patch.
inline constexpr int kMinWoodruffStems = 16;
/// Range of leaf whorls per woodruff stem.
inline constexpr int kWoodruffLevels[2] = {3, 4};
/// Range of a woodruff whorl's nominal span, metres (Galium odoratum: leaves 2-5 cm long).
inline constexpr float kWoodruffWhorlSpan[2] = {0.05f, 0.08f};
/// Share of its card's side a woodruff whorl spans (the mask's leaves reach 0.46 from the centre).
inline constexpr float kWoodruffWhorlFill = 0.92f;
/// Wood anemone (spring only): a carpet patch of kMinWoodAnemoneStems-50 stems 5.5-25 cm high, each with one whorl of
/// three palmately cut leaves kWoodAnemoneWhorlSpan across kWoodAnemoneFlowerStalk of the stem below its top, and on
/// kWoodAnemoneFlowering of the stems a white flower kWoodAnemoneFlowerSpan across at the top.
GeneratedAsset generate_wood_anemone(Rng& rng);
/// Fewest stems of a wood anemone patch.
inline constexpr int kMinWoodAnemoneStems = 20;
/// Range of a wood anemone leaf whorl's nominal span, metres (Anemone nemorosa: leaves 3-6 cm, the whorl 6-12 cm).
inline constexpr float kWoodAnemoneWhorlSpan[2] = {0.065f, 0.11f};
/// Share of its card's side a wood anemone whorl spans (the mask's leaves reach 0.46 from the centre).
inline constexpr float kWoodAnemoneWhorlFill = 0.92f;
/// Share of a wood anemone stem between its leaf whorl and its flower (the flower stalk).
inline constexpr float kWoodAnemoneFlowerStalk = 0.25f;
/// Range of a wood anemone flower's span, metres (2-4 cm across).
inline constexpr float kWoodAnemoneFlowerSpan[2] = {0.022f, 0.038f};
/// Share of wood anemone stems that flower.
inline constexpr float kWoodAnemoneFlowering = 0.75f;
/// Stinging nettle: a clonal patch of kMinNettleStems-32 upright stems 0.28-1.1 m high, each with kNettleLevels
/// opposite pairs of toothed leaves kNettlePairSpan across (the top pair smaller) down its upper part, drooping;
/// the fern's material (green, autumn-brown, dead grey-brown stems in winter); grown as a fern-layer herb.
GeneratedAsset generate_nettle(Rng& rng);
/// Young nettle shoots in spring: the patch's stems 0.1-0.35 m high with kYoungNettleLevels crowded leaf
/// pairs kYoungNettlePairSpan across.
GeneratedAsset generate_young_nettle(Rng& rng);
/// Range of leaf pairs on a young nettle shoot (7 % of its height apart).
inline constexpr int kYoungNettleLevels[2] = {3, 5};
/// Range of a young nettle leaf pair's nominal span, metres (leaves 3-7 cm long).
inline constexpr float kYoungNettlePairSpan[2] = {0.07f, 0.14f};
/// Fewest stems of a nettle patch.
inline constexpr int kMinNettleStems = 16;
/// Range of leaf pairs per nettle stem (a tenth of its height apart).
inline constexpr int kNettleLevels[2] = {6, 9};
/// Range of a nettle leaf pair's nominal span, metres (Urtica dioica: leaves 4-15 cm long, 5-10 cm typically).
inline constexpr float kNettlePairSpan[2] = {0.14f, 0.24f};
/// Share of its card's side a nettle leaf pair spans (the mask's leaves reach 0.46 from the centre).
inline constexpr float kNettlePairFill = 0.92f;
/// Bilberry: dense dwarf shrub 0.2-0.5 m, 14-27 green ribbon stems carrying small-leaf cards.
GeneratedAsset generate_bilberry(Rng& rng);
/// Hazel: multi-stem shrub 2-5 m, 5-11 fanning stems (tubes, ribbons where thin) with side
/// branches and cards of broad round leaves.
GeneratedAsset generate_hazel(Rng& rng);
/// Bramble: 0.5-1.5 m, 6-12 arching canes (ribbons) bowing back to the ground, compound leaves.
GeneratedAsset generate_bramble(Rng& rng);
/// Rock: 0.3-1.5 m, icosphere displaced by fBm and ridged noise, cut by fracture planes,
/// flattened and partly buried.
GeneratedAsset generate_rock(Rng& rng);
/// Log: 3-6 m long, 0.3-0.6 m thick, lying along X, bumpy bark, branch stubs, ends mostly
/// broken into splinters (else sawn).
GeneratedAsset generate_log(Rng& rng);
/// Twig on the ground: 0.15-0.4 m, thin ribbons with a few side twigs.
GeneratedAsset generate_twig(Rng& rng);
/// Small fallen branch: 0.28-0.42 m, 1.5-3 cm radius (a tube) with ribbon side twigs.
GeneratedAsset generate_fallen_branch(Rng& rng);
/// Conifer cone lying on the ground: spruce (8-15 cm, slim) or pine (4-7 cm, ovoid), scaly.
GeneratedAsset generate_cone(Rng& rng);
/// Leaf-litter cluster: 3-7 nearly flat, slightly curled cards of fallen leaves, <= 0.5 m.
GeneratedAsset generate_leaf_litter(Rng& rng);
/// Moss cushion: a lumpy flattened dome 0.1-0.3 m across, with up to two smaller ones beside it.
GeneratedAsset generate_moss_cushion(Rng& rng);

/// Quads along each fern frond.
inline constexpr int kFrondSegments = 8;

/// Vertical-cylinder proxy from the ground up: radius r, height h.
CollisionProxy cylinder_proxy(float r, float h);

/// A random unit vector (uniform on the sphere).
Vec3f random_direction(Rng& rng);

}  // namespace silva::assets
