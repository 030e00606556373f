#pragma once
/// @file Every procedural-shading noise salt in one table, so that no two patterns share a noise
/// stream. An fBm of n octaves uses salts salt .. salt + n - 1 and some patterns add small offsets,
/// so salts are 0x20 apart. (Sky clouds and stars keep their own salts in render/sky.cpp.)
#include <cstdint>

namespace silva::render {

/// Noise salts of the procedural materials.
enum NoiseSalt : uint32_t {
  // Forest floor (render/materials.hpp formula).
  kGroundStandSalt = 0x100,  ///< Leaf vs needle litter stands.
  kGroundGrassSalt = 0x120,  ///< Grassy openings.
  kGroundMossSalt = 0x140,   ///< Moss carpets.
  kGroundSoilSalt = 0x160,   ///< Bare-soil patches.
  kGroundFineSalt = 0x180,   ///< Brightness grain.
  kGroundLeafSalt = 0x1a0,   ///< Leaf-sized blotches (and + 1: speckle).
  kGroundFallenSalt = 0x1c0, ///< Drifts of freshly fallen autumn leaves (and + 8: their hue).
  kGroundLitterSalt = 0x1e0, ///< Single leaves, needles and twigs (render/floor_litter.hpp).
  kGroundCushionSalt = 0x200, ///< Moss cushions and their tips (and + 1).
  kGroundConeSalt = 0x220,   ///< Spruce cones (render/floor_litter.hpp).
  // Trail (render/trail_material.cpp).
  kTrailSoil = 0x400,        ///< Compacted soil patches and grit.
  kTrailStone = 0x420,       ///< Embedded stones.
  kTrailRoot = 0x440,        ///< Roots crossing.
  kTrailLitter = 0x460,      ///< Litter drifting in at the edges.
  kTrailFringe = 0x480,      ///< Worn grassy fringe.
  // 0x4a0: the ragged edge of the overlay (kOverlayEdgeSalt, core/surface_overlay.cpp).
  kTrailGravel = 0x4c0,      ///< Gravel stones and bed.
  kTrailRut = 0x4e0,         ///< Ruts, mud and the grass between them.
  kTrailWater = 0x500,       ///< Water standing in a muddy trail's ruts.
  // Bark, foliage and wood (render/materials.cpp).
  kBarkStreak = 0x600,       ///< Vertical bark streaks.
  kBarkLichen = 0x620,       ///< Lichen on bark.
  kFoliage = 0x640,          ///< Per-instance tint and mottling.
  kWood = 0x660,             ///< Cut wood rings.
  kAutumnTurn = 0x680,       ///< How far autumn leaves have turned, patch by patch.
  // Species barks (render/bark_materials.cpp).
  kBarkFurrow = 0x700,       ///< Furrows.
  kBarkPlate = 0x720,        ///< Plates and flakes.
  kBarkMark = 0x740,         ///< Birch marks; beech lichen (+1) and wrinkles (+2).
  kBarkBlotch = 0x760,       ///< Blotches.
  // Rocks, logs, moss and litter (render/ground_object_materials.cpp).
  kRockGrain = 0x900,        ///< Rock grain.
  kRockMoss = 0x920,         ///< Moss on rocks.
  kRockLichen = 0x940,       ///< Lichen patches.
  kRockBand = 0x960,         ///< Mineral bands.
  kLogFurrow = 0x980,        ///< Log bark furrows.
  kLogMoss = 0x9a0,          ///< Moss on logs.
  kBrokenGrain = 0x9c0,      ///< Broken wood grain.
  kMossMottle = 0x9e0,       ///< Moss cushion mottling.
  kLitterTone = 0xa00,       ///< Leaf litter tones.
  kSoilTone = 0xa20,         ///< Soil: humus and mineral patches, crumbs, stones.
};

}  // namespace silva::render
