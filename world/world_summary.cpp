#include "world/world_summary.hpp"

#include <xxhash.h>

#include <algorithm>
#include <cstring>
#include <utility>

namespace silva::world {

namespace {

/// Feeds a vector's size and its elements' coefficients to the hash state, the whole array at once (the
/// elements are packed coefficients, so this is the bytes of feeding them one by one).
template <class T>
void feed(XXH3_state_t* st, const std::vector<T>& v) {
  static_assert(sizeof(T) == sizeof(typename T::Scalar) * size_t(T::SizeAtCompileTime), "packed coefficients");
  const uint64_t n = v.size();
  XXH3_64bits_update(st, &n, sizeof n);
  XXH3_64bits_update(st, v.data(), sizeof(T) * v.size());
}

/// Feeds a mesh (positions, normals, uvs, indices, part roles/materials).
void feed_mesh(XXH3_state_t* st, const Mesh& m) {
  feed(st, m.positions);
  feed(st, m.normals);
  feed(st, m.uvs);
  XXH3_64bits_update(st, m.indices.data(), m.indices.size() * sizeof(uint32_t));
  for (const MeshPart& p : m.parts) {
    const uint32_t overlay = p.overlay ? 1u << 16 | uint32_t(p.overlay->role) << 8 | uint32_t(p.overlay->material) : 0u;
    const uint32_t w[5] = {p.first_index, p.index_count, uint32_t(p.role), uint32_t(p.material), overlay};
    XXH3_64bits_update(st, w, sizeof w);
  }
}

/// Feeds one chunk's content.
void feed_chunk(XXH3_state_t* st, const ChunkContent& c) {
  const int32_t ij[2] = {c.coord.i, c.coord.j};
  XXH3_64bits_update(st, ij, sizeof ij);
  feed_mesh(st, c.terrain);
  // Per object its four words then its five floats, gathered into one buffer and fed at once.
  constexpr size_t kObjectBytes = 4 * sizeof(uint32_t) + 5 * sizeof(float);
  std::vector<unsigned char> bytes(c.objects.size() * kObjectBytes);
  unsigned char* out = bytes.data();
  for (const Vegetation& v : c.objects) {
    const uint32_t w[4] = {v.asset, uint32_t(v.role), uint32_t(v.placement), v.instance_id};
    const float f[5] = {v.position.x(), v.position.y(), v.position.z(), v.yaw, v.scale};
    std::memcpy(out, w, sizeof w);
    std::memcpy(out + sizeof w, f, sizeof f);
    out += kObjectBytes;
  }
  XXH3_64bits_update(st, bytes.data(), bytes.size());
}

/// Hash of chunks fed in order.
uint64_t hash_of(const ChunkContent* begin, const ChunkContent* end) {
  XXH3_state_t* st = XXH3_createState();
  XXH3_64bits_reset(st);
  for (const ChunkContent* c = begin; c != end; ++c) feed_chunk(st, *c);
  const uint64_t h = XXH3_64bits_digest(st);
  XXH3_freeState(st);
  return h;
}

}  // namespace

void accumulate(WorldTotals& t, const ChunkStats& s) {
  ++t.chunks;
  t.triangles += s.triangles;
  for (size_t r = 0; r < s.objects_by_role.size(); ++r) {
    t.objects_by_role[r] += s.objects_by_role[r];
    t.objects += s.objects_by_role[r];
  }
  t.candidates += s.candidates;
  t.trail_rejected += s.trail_rejected;
  t.adjusted += s.adjusted;
  t.dropped += s.dropped;
  t.ground_dropped += s.ground_dropped;
  t.broad_queries += s.broad_queries;
  t.narrow_queries += s.narrow_queries;
  t.terrain_cpu_s += s.generate_s;
  t.resolve_cpu_s += s.resolve_s;
}


uint64_t world_hash(const std::vector<ChunkContent>& chunks) {
  return hash_of(chunks.data(), chunks.data() + chunks.size());
}

uint64_t chunk_hash(const ChunkContent& chunk) { return hash_of(&chunk, &chunk + 1); }

BuiltWorld summarise_world(std::vector<ChunkContent> chunks) {
  BuiltWorld w;
  w.chunks = std::move(chunks);
  std::sort(w.chunks.begin(), w.chunks.end(),
            [](const ChunkContent& a, const ChunkContent& b) { return a.coord < b.coord; });
  for (const ChunkContent& c : w.chunks) accumulate(w.totals, c.stats);
  std::vector<bool> used;  // by asset index
  for (const ChunkContent& c : w.chunks)
    for (const Vegetation& v : c.objects) {
      if (v.asset >= used.size()) used.resize(size_t(v.asset) + 1, false);
      if (!used[v.asset]) {
        used[v.asset] = true;
        ++w.totals.distinct_assets;
      }
    }
  w.hash = world_hash(w.chunks);
  return w;
}

}  // namespace silva::world
