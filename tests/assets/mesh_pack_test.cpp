#include "assets/mesh_pack.hpp"

#include <gtest/gtest.h>

#include <map>

#include "assets/factory.hpp"
#include "assets/lod.hpp"
#include "tests/common/mesh_equal.hpp"

namespace silva::assets {
namespace {

/// A variant's LOD chain as the library builds it.
std::vector<Mesh> variant_lods(const char* generator, uint32_t variant) {
  return build_lods(generate_variant(*find_factory(generator), kDefaultAssetSeed, variant, Season::Summer).mesh).lods;
}

/// Unpacks with a lookup that serves the pack's own masks (new objects, as read from files).
std::optional<std::vector<Mesh>> round_trip(const PackedLods& packed) {
  std::map<uint64_t, std::shared_ptr<const AlphaMask>> files;
  for (const auto& [hash, mask] : packed.masks) files[hash] = std::make_shared<const AlphaMask>(*mask);
  return unpack_lods(packed.bytes, [&](uint64_t h) { return files.count(h) ? files[h] : nullptr; });
}

TEST(MeshPack, TreeAndFernLodsComeBackBitForBit) {
  for (const char* generator : {"spruce", "beech", "fern", "rock"}) {
    const std::vector<Mesh> lods = variant_lods(generator, 3);
    ASSERT_TRUE(packable(lods));
    const PackedLods packed = pack_lods(lods);
    const std::optional<std::vector<Mesh>> back = round_trip(packed);
    ASSERT_TRUE(back) << generator;
    ASSERT_EQ(back->size(), lods.size()) << generator;
    for (size_t k = 0; k < lods.size(); ++k)
      test::expect_same_mesh((*back)[k], lods[k], std::string(generator) + " lod " + std::to_string(k));
  }
}

TEST(MeshPack, PartsSharingAMaskShareItUnpackedAndEachMaskIsNamedOnce) {
  const std::vector<Mesh> lods = variant_lods("spruce", 0);
  const PackedLods packed = pack_lods(lods);
  ASSERT_FALSE(packed.masks.empty());
  for (size_t i = 0; i < packed.masks.size(); ++i)
    for (size_t j = i + 1; j < packed.masks.size(); ++j) EXPECT_NE(packed.masks[i].first, packed.masks[j].first);
  const std::optional<std::vector<Mesh>> back = round_trip(packed);
  ASSERT_TRUE(back);
  // Card parts of every level drew one mask object each: so do the unpacked ones.
  for (size_t k = 0; k < lods.size(); ++k)
    for (size_t p = 0; p < lods[k].parts.size(); ++p)
      for (size_t q = 0; q < lods[0].parts.size(); ++q)
        if (lods[k].parts[p].mask && lods[k].parts[p].mask == lods[0].parts[q].mask) {
          EXPECT_EQ((*back)[k].parts[p].mask, (*back)[0].parts[q].mask);
        }
}

TEST(MeshPack, OverlaysAndSidednessSurvive) {
  Mesh m;
  m.positions = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0)};
  m.uvs = {Vec2f(-0.5f, 0), Vec2f(0.25f, 1), Vec2f(3, 0)};
  m.indices = {0, 1, 2};
  m.compute_normals();
  MeshPart part;
  part.index_count = 3;
  part.double_sided = true;
  part.overlay = PartOverlay{Role::Trail, Material::Trail};
  m.parts = {part};
  const std::vector<Mesh> lods = {m};
  const std::optional<std::vector<Mesh>> back = round_trip(pack_lods(lods));
  ASSERT_TRUE(back);
  test::expect_same_mesh(back->at(0), m, "overlay mesh");
}

TEST(MeshPack, DamagedPacksAreRefusedNotRead) {
  const std::vector<Mesh> lods = variant_lods("fern", 1);
  const PackedLods packed = pack_lods(lods);
  ASSERT_TRUE(round_trip(packed));
  for (const size_t cut : {size_t(0), size_t(7), size_t(20), packed.bytes.size() / 2, packed.bytes.size() - 1}) {
    PackedLods truncated = packed;
    truncated.bytes.resize(cut);
    EXPECT_FALSE(round_trip(truncated)) << "cut at " << cut;
  }
  for (const size_t at : {size_t(3), size_t(10), size_t(40), packed.bytes.size() / 3, packed.bytes.size() - 5}) {
    PackedLods flipped = packed;
    flipped.bytes[at] = char(flipped.bytes[at] ^ 0x10);
    EXPECT_FALSE(round_trip(flipped)) << "byte " << at << " flipped";
  }
  PackedLods longer = packed;
  longer.bytes += "x";
  EXPECT_FALSE(round_trip(longer));
  // A mask the lookup cannot find fails the whole pack.
  EXPECT_FALSE(unpack_lods(packed.bytes, [](uint64_t) { return nullptr; }));
}

TEST(MeshPack, AnIndexPastTheVerticesIsRefusedThoughTheChecksumHolds) {
  Mesh m;
  m.positions = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0)};
  m.indices = {0, 1, 3};
  MeshPart part;
  part.index_count = 3;
  m.parts = {part};
  const std::vector<Mesh> bad_index = {m};
  EXPECT_FALSE(round_trip(pack_lods(bad_index)));
  m.indices = {0, 1, 2};
  m.parts[0].index_count = 6;
  const std::vector<Mesh> bad_part = {m};
  EXPECT_FALSE(round_trip(pack_lods(bad_part)));
}

TEST(MeshPack, MasksRoundTripAndTheirHashFollowsTheirContent) {
  AlphaMask mask;
  mask.width = 4;
  mask.height = 2;
  mask.alpha = {0, 255, 130, 200, 7, 0, 128, 254};
  mask.cutoff = 0.5f;
  mask.feature_length = 0.125f;
  const std::optional<AlphaMask> back = unpack_mask(pack_mask(mask));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->alpha, mask.alpha);
  EXPECT_EQ(back->width, 4);
  EXPECT_EQ(back->feature_length, 0.125f);
  EXPECT_EQ(mask_hash(*back), mask_hash(mask));
  AlphaMask other = mask;
  other.alpha[5] = 1;
  EXPECT_NE(mask_hash(other), mask_hash(mask));
  other = mask;
  other.width = 2, other.height = 4;
  EXPECT_NE(mask_hash(other), mask_hash(mask));
  std::string bytes = pack_mask(mask);
  bytes.back() = char(bytes.back() ^ 1);
  EXPECT_FALSE(unpack_mask(bytes));
  // A mask's pack is not a pack of meshes.
  EXPECT_FALSE(unpack_lods(pack_mask(mask), [](uint64_t) { return nullptr; }));
}

}  // namespace
}  // namespace silva::assets
