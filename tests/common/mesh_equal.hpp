#pragma once
/// @file Bit-for-bit comparison of meshes for tests: arrays, parts and mask contents.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/mesh.hpp"

namespace silva::test {

/// True when two arrays hold the same bytes.
template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// Expects `got` to equal `want` bit for bit: positions, normals, uvs, indices, and each part's
/// range, role, material, sidedness, overlay and mask content (`what` names it in failures).
inline void expect_same_mesh(const Mesh& got, const Mesh& want, const std::string& what) {
  EXPECT_TRUE(same_bytes(got.positions, want.positions)) << what << " positions";
  EXPECT_TRUE(same_bytes(got.normals, want.normals)) << what << " normals";
  EXPECT_TRUE(same_bytes(got.uvs, want.uvs)) << what << " uvs";
  EXPECT_EQ(got.indices, want.indices) << what << " indices";
  ASSERT_EQ(got.parts.size(), want.parts.size()) << what;
  for (size_t p = 0; p < want.parts.size(); ++p) {
    const MeshPart &g = got.parts[p], &w = want.parts[p];
    EXPECT_EQ(g.first_index, w.first_index) << what << " part " << p;
    EXPECT_EQ(g.index_count, w.index_count) << what << " part " << p;
    EXPECT_EQ(g.role, w.role) << what << " part " << p;
    EXPECT_EQ(g.material, w.material) << what << " part " << p;
    EXPECT_EQ(g.double_sided, w.double_sided) << what << " part " << p;
    ASSERT_EQ(g.overlay.has_value(), w.overlay.has_value()) << what << " part " << p;
    if (w.overlay) {
      EXPECT_EQ(g.overlay->role, w.overlay->role) << what << " part " << p;
      EXPECT_EQ(g.overlay->material, w.overlay->material) << what << " part " << p;
    }
    ASSERT_EQ(g.mask != nullptr, w.mask != nullptr) << what << " part " << p;
    if (!w.mask) continue;
    EXPECT_EQ(g.mask->width, w.mask->width) << what << " part " << p;
    EXPECT_EQ(g.mask->height, w.mask->height) << what << " part " << p;
    EXPECT_EQ(g.mask->cutoff, w.mask->cutoff) << what << " part " << p;
    EXPECT_EQ(g.mask->feature_length, w.mask->feature_length) << what << " part " << p;
    EXPECT_TRUE(g.mask->alpha == w.mask->alpha) << what << " part " << p << " mask texels";
  }
}

}  // namespace silva::test
