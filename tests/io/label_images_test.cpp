#include "io/label_images.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io_test_util.hpp"

namespace silva::io {
namespace {

TEST(LabelImages, DepthMillimetresKnownAnswers) {
  EXPECT_EQ(depth_to_mm(0.0f), 0);
  EXPECT_EQ(depth_to_mm(-1.0f), 0);
  EXPECT_EQ(depth_to_mm(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(depth_to_mm(0.0001f), 1);  // a hit is never 0
  EXPECT_EQ(depth_to_mm(0.25f), 250);
  EXPECT_EQ(depth_to_mm(0.0625f), 63);  // 62.5 rounds half away from zero
  EXPECT_EQ(depth_to_mm(65.5f), 65500);
  EXPECT_EQ(depth_to_mm(65.536f), 65535);
  EXPECT_EQ(depth_to_mm(149.0f), 65535);
  EXPECT_EQ(depth_to_mm(std::numeric_limits<float>::infinity()), 65535);
}

TEST(LabelImages, DepthPreviewKnownAnswers) {
  EXPECT_EQ(depth_to_preview(0.0f), 0);
  EXPECT_EQ(depth_to_preview(0.001f), 255);
  EXPECT_EQ(depth_to_preview(10.0f), 94);   // 255/e = 93.81
  EXPECT_EQ(depth_to_preview(20.0f), 35);   // 255/e^2 = 34.51
  EXPECT_EQ(depth_to_preview(60.0f), 1);    // 0.63 rounds to 1
  EXPECT_EQ(depth_to_preview(140.0f), 1);   // 0 -> at least 1 for a hit
}

TEST(LabelImages, NormalByteKnownAnswers) {
  EXPECT_EQ(normal_to_byte(-1.0f), 0);
  EXPECT_EQ(normal_to_byte(0.0f), 128);  // 127.5 rounds up
  EXPECT_EQ(normal_to_byte(0.5f), 191);  // 191.25
  EXPECT_EQ(normal_to_byte(1.0f), 255);
  EXPECT_EQ(normal_to_byte(1.0001f), 255);
  EXPECT_EQ(normal_to_byte(-0.5f), 64);  // 63.75
}

TEST(LabelImages, NoHitPixelsAreZeroEverywhere) {
  const auto g = test::synthetic_gbuffer();
  const auto depth = depth_mm_image(g);
  const auto preview = depth_preview_image(g);
  const auto normal = normal_image(g);
  const auto sem = semantic_image(g, default_ontology());
  for (size_t i = 0; i < g.size(); ++i) {
    const bool hit = g.depth[i] > 0;
    EXPECT_EQ(depth[i] != 0, hit);
    EXPECT_EQ(preview[i] != 0, hit);
    EXPECT_EQ(normal[3 * i] || normal[3 * i + 1] || normal[3 * i + 2], hit);
    if (!hit) {
      EXPECT_EQ(sem[i], 0);
    }
  }
}

TEST(LabelImages, SemanticUsesOntologyIdsAndColours) {
  Ontology o = default_ontology();
  o.classes[uint8_t(Role::Trail)].id = 200;
  o.classes[uint8_t(Role::Trail)].color = {1, 2, 3};
  const auto g = test::synthetic_gbuffer();
  const auto ids = semantic_image(g, o);
  const auto rgb = semantic_color_image(g, o);
  for (size_t i = 0; i < g.size(); ++i) {
    EXPECT_EQ(ids[i], o.id(g.role[i]));
    for (int a = 0; a < 3; ++a) EXPECT_EQ(rgb[3 * i + a], o.color(g.role[i])[a]);
  }
}

TEST(LabelImages, InstanceIndicesAscendByInstanceIdAndMatchPixels) {
  const auto g = test::synthetic_gbuffer();
  const Ontology o = default_ontology();
  const InstanceImage inst = instance_image(g, o);
  ASSERT_GT(inst.entries.size(), 5u);
  for (size_t k = 0; k < inst.entries.size(); ++k) {
    EXPECT_EQ(inst.entries[k].index, k + 1);
    if (k > 0) {
      EXPECT_LT(inst.entries[k - 1].instance_id, inst.entries[k].instance_id);
    }
  }
  std::vector<bool> used(inst.entries.size(), false);
  for (size_t i = 0; i < g.size(); ++i) {
    const uint16_t idx = inst.pixels[i];
    if (!role_has_instances(g.role[i]) || g.instance_id[i] == 0) {
      EXPECT_EQ(idx, 0);  // stuff and canopy carry no instance
      continue;
    }
    ASSERT_GE(idx, 1);
    const InstanceEntry& e = inst.entries[idx - 1];
    EXPECT_EQ(e.instance_id, g.instance_id[i]);
    EXPECT_EQ(e.class_id, o.id(g.role[i]));
    used[idx - 1] = true;
  }
  for (bool u : used) EXPECT_TRUE(u);  // no entry without pixels
}

TEST(LabelImages, InstanceClassIsLowestRoleOfItsPixels) {
  test::TestGBuffer g;
  g.resize(3, 1);
  for (int i = 0; i < 3; ++i) {
    g.depth[i] = 1.0f;
    g.instance_id[i] = 42;
  }
  g.role = {Role::Obstacle, Role::Stump, Role::Obstacle};
  const InstanceImage inst = instance_image(g, default_ontology());
  ASSERT_EQ(inst.entries.size(), 1u);
  EXPECT_EQ(inst.entries[0], (InstanceEntry{1, 42, uint8_t(Role::Stump)}));
}

TEST(LabelImages, InstanceTableJsonLayout) {
  const std::vector<InstanceEntry> entries = {{1, 5, 3}, {2, 0x01020003, 9}};
  const auto j = nlohmann::json::parse(instance_table_json(entries));
  ASSERT_EQ(j.at("instances").size(), 2u);
  EXPECT_EQ(j["instances"][1]["index"], 2);
  EXPECT_EQ(j["instances"][1]["instance_id"], 0x01020003);
  EXPECT_EQ(j["instances"][1]["class_id"], 9);
  EXPECT_EQ(instance_table_json({}), "{\n  \"instances\": []\n}\n");
}

TEST(LabelImages, MoreThan65535InstancesIsAClearError) {
  test::TestGBuffer g;
  g.resize(300, 220);
  for (size_t i = 0; i < g.size(); ++i) {
    g.depth[i] = 1.0f;
    g.role[i] = Role::Obstacle;
    g.instance_id[i] = uint32_t(i + 1);
  }
  try {
    instance_image(g, default_ontology());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("65535"), std::string::npos);
  }
  g.resize(255, 257);  // exactly 65535 instances is fine
  for (size_t i = 0; i < g.size(); ++i) {
    g.depth[i] = 1.0f;
    g.role[i] = Role::Obstacle;
    g.instance_id[i] = uint32_t(g.size() - i);
  }
  const InstanceImage inst = instance_image(g, default_ontology());
  EXPECT_EQ(inst.entries.size(), 65535u);
  EXPECT_EQ(inst.pixels[0], 65535);
  EXPECT_EQ(inst.pixels.back(), 1);
}

}  // namespace
}  // namespace silva::io
