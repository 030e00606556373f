#include "app/commands/assets/asset_sheet.hpp"

#include <gtest/gtest.h>

#include "core/ontology.hpp"

namespace silva::app {
namespace {

TEST(AssetSheet, SelectsByKindOrGeneratorName) {
  const auto rocks = select_factories("rock");
  ASSERT_FALSE(rocks.empty());
  for (const assets::Factory* f : rocks) EXPECT_EQ(f->kind, AssetKind::Rock);
  const assets::Factory& first = assets::factories()[0];
  const auto one = select_factories(first.prefix);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], &first);
  EXPECT_TRUE(select_factories("no_such_kind").empty());
  const auto both = select_factories(std::string("rock,") + first.prefix + ",rock");
  EXPECT_EQ(both.size(), rocks.size() + 1);  // each factory once
  EXPECT_TRUE(select_factories("rock,no_such_kind").empty());
  EXPECT_TRUE(select_factories("rock,").empty());
}

/// Counts pixels of `rgb` (interleaved) in columns [x0, x1) that have colour `c`.
int count_colour(const std::vector<uint8_t>& rgb, int width, int x0, int x1, const std::array<uint8_t, 3>& c) {
  int n = 0;
  for (size_t p = 0; p < rgb.size() / 3; ++p) {
    const int x = int(p % size_t(width));
    if (x >= x0 && x < x1 && rgb[3 * p] == c[0] && rgb[3 * p + 1] == c[1] && rgb[3 * p + 2] == c[2]) ++n;
  }
  return n;
}

TEST(AssetSheet, EachVariantHasAnRgbViewAndItsSemanticView) {
  const auto factories = select_factories("stump");
  ASSERT_FALSE(factories.empty());
  int w = 0, h = 0;
  const std::vector<uint8_t> sheet = render_asset_sheet({factories[0]}, 2, 7, {96, 2}, w, h);
  EXPECT_EQ(w, 2 * 2 * 96);
  EXPECT_EQ(h, 96);
  ASSERT_EQ(sheet.size(), size_t(w) * size_t(h) * 3);
  const Ontology o = default_ontology();
  for (int v = 0; v < 2; ++v) {
    const int rgb0 = v * 2 * 96, sem0 = rgb0 + 96;
    // The semantic view shows the asset's class and the ground; the RGB view shows neither colour.
    EXPECT_GT(count_colour(sheet, w, sem0, sem0 + 96, o.color(Role::Stump)), 50) << "variant " << v;
    EXPECT_GT(count_colour(sheet, w, sem0, sem0 + 96, o.color(Role::Ground)), 500) << "variant " << v;
    EXPECT_LT(count_colour(sheet, w, rgb0, rgb0 + 96, o.color(Role::Stump)), 5) << "variant " << v;
  }
}

}  // namespace
}  // namespace silva::app
