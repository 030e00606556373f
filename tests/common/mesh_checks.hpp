#pragma once
/// @file Test helper: structural validity of a Mesh (shared by the asset tests).
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh.hpp"

namespace silva::assets::test {

/// Checks indices in range, finite attributes, unit normals and parts covering the indices in order.
inline void expect_valid_mesh(const Mesh& m, const std::string& what) {
  SCOPED_TRACE(what);
  const size_t nv = m.positions.size();
  ASSERT_GT(nv, 0u);
  ASSERT_EQ(m.normals.size(), nv);
  ASSERT_EQ(m.uvs.size(), nv);
  ASSERT_EQ(m.indices.size() % 3, 0u);
  for (uint32_t i : m.indices) ASSERT_LT(i, nv);
  for (size_t v = 0; v < nv; ++v) {
    ASSERT_TRUE(m.positions[v].allFinite());
    ASSERT_TRUE(m.uvs[v].allFinite());
    ASSERT_NEAR(m.normals[v].norm(), 1.0f, 1e-4f);
  }
  uint32_t next = 0;
  for (const MeshPart& p : m.parts) {
    EXPECT_EQ(p.first_index, next);
    EXPECT_GT(p.index_count, 0u);
    EXPECT_EQ(p.index_count % 3, 0u);
    next = p.first_index + p.index_count;
    if (p.mask) {
      EXPECT_TRUE(p.double_sided);
      EXPECT_EQ(p.mask->alpha.size(), size_t(p.mask->width) * size_t(p.mask->height));
    }
  }
  EXPECT_EQ(next, m.indices.size());
}

}  // namespace silva::assets::test
