#include "world/placement.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "world/class_mix.hpp"

namespace silva::world {

using assets::AssetKind;

namespace {

constexpr double kTwoPi = 6.283185307179586;

/// Per-point draw streams: every attribute has its own purpose, keyed by (chunk, point).
struct PointDraws {
  uint64_t seed, key;
  /// Stream for one purpose; `sub` separates the objects of one point.
  Rng stream(Purpose p, uint32_t sub) const { return Rng(seed, key, p, uint64_t(sub) * 8); }
};

/// Ground points hold kMinTufts..kMinTufts+kTuftRange-1 grass/fern tufts (ferns grow more under
/// denser canopy) and 0..kMaxDebris-1 pieces of ground-cover debris (twigs, cones, litter, moss).
constexpr uint32_t kMinTufts = 3;
constexpr uint32_t kTuftRange = 4;
/// Vernal points hold this many times a ground point's tufts: vernal herbs carpet the floor they take.
constexpr uint32_t kVernalTufts = 2;
constexpr uint32_t kMaxDebris = 3;

/// Sets the terrain height of every candidate of `list` (their world x, y in double in `x`, `y`).
void fill_heights(const TerrainField& terrain, const std::vector<double>& x, const std::vector<double>& y,
                  std::vector<Candidate>& list) {
  std::vector<float> z(list.size());
  terrain_heights(terrain, x.data(), y.data(), z.data(), list.size());
  for (size_t k = 0; k < list.size(); ++k) list[k].position.z() = z[k];
}

}  // namespace

bool outranks(const Candidate& a, const Candidate& b) {
  if (a.rank != b.rank) return a.rank < b.rank;
  if (a.priority != b.priority) return a.priority > b.priority;
  if (a.chunk_key != b.chunk_key) return a.chunk_key < b.chunk_key;
  if (a.point != b.point) return a.point < b.point;
  return a.sub < b.sub;
}

ChunkCandidates place_candidates(const WorldContext& ctx, ChunkCoord coord, bool with_ground) {
  const Config& cfg = ctx.config;
  const auto& lib = *ctx.library;
  const double s = cfg.terrain.chunk_size, gs = cfg.vegetation.grid_spacing;
  const int n = int(std::lround(s / gs));
  const double radius = kAdmissibleFraction * gs;
  const ClassMix mix = class_mix(cfg.vegetation.density, cfg.vegetation.ground, *ctx.forest, ctx.season);
  const double fern_share = std::clamp(0.35 + 2.0 * cfg.vegetation.density / 100.0 + ctx.forest->fern_bias, 0.0, 1.0);
  const double x0 = coord.i * s, y0 = coord.j * s;
  const double pad = ctx.trail.corridor_half_width() + std::max<double>(ctx.max_footprint, kGroundFootprint * kMaxScale);
  const auto trail_segments = trail_segments_near(ctx.trail, x0, y0, x0 + s, y0 + s, pad);
  const double corridor = ctx.trail.corridor_half_width();

  ChunkCandidates out;
  // Each candidate's (x, y) in double, beside out.solids and out.ground: heights are filled in at the end,
  // all of a list at once.
  std::vector<double> solid_x, solid_y, ground_x, ground_y;
  auto propose = [&](AssetKind kind, const PointDraws& d, uint32_t point, uint32_t sub, double cx, double cy,
                     bool vernal = false) {
    Rng pos = d.stream(Purpose::PlacementPosition, sub);
    const double r = radius * std::sqrt(pos.uniform_double()), th = kTwoPi * pos.uniform_double();
    const double x = cx + r * std::cos(th), y = cy + r * std::sin(th);
    Rng variant = d.stream(Purpose::PlacementVariant, sub);
    Candidate c;
    c.asset = vernal ? pick_vernal(ctx.stands, variant) : pick_asset(ctx.stands, kind, x, y, variant);
    if (c.asset == UINT32_MAX) return;
    c.kind = kind;
    const auto sr = scale_range(kind);
    c.scale = d.stream(Purpose::PlacementScale, sub).range(sr[0], sr[1]);
    c.footprint = ctx.footprint[c.asset] * c.scale;
    if (!trail_segments.empty() && trail_distance(ctx.trail, trail_segments, x, y) < corridor + c.footprint) {
      ++out.trail_rejected;
      return;
    }
    c.yaw = float(kTwoPi * d.stream(Purpose::PlacementYaw, sub).uniform_double());
    c.position = Vec3f(float(x), float(y), 0.0f);
    c.point = point;
    c.sub = uint16_t(sub);
    c.rank = kind_rank(kind);
    c.chunk_key = coord.key();
    c.priority = rng_bits(d.seed, d.key, uint64_t(Purpose::ResolvePriority), sub);
    const bool solid = is_solid(kind) && lib.assets[c.asset].proxy.shape != assets::CollisionProxy::Shape::None;
    (solid ? out.solids : out.ground).push_back(c);
    (solid ? solid_x : ground_x).push_back(x);
    (solid ? solid_y : ground_y).push_back(y);
  };

  for (int gy = 0; gy < n; ++gy) {
    for (int gx = 0; gx < n; ++gx) {
      const uint32_t point = uint32_t(gy * n + gx);
      const PointDraws d{uint64_t(cfg.seed), hash_combine(coord.key(), point)};
      const double cx = x0 + (gx + 0.5) * gs, cy = y0 + (gy + 0.5) * gs;
      const PointClass cls = pick_class(mix, d.stream(Purpose::PlacementClass, 0).uniform_double());
      if (cls == PointClass::Nothing) continue;
      if (cls != PointClass::Ground && cls != PointClass::Vernal) {
        propose(kind_of(cls), d, point, 0, cx, cy);
        continue;
      }
      if (!with_ground) continue;
      Rng cover = d.stream(Purpose::GroundCover, 0);
      const uint32_t tufts = kMinTufts + cover.below(kTuftRange);
      if (cls == PointClass::Vernal) {  // a carpet of vernal herbs on otherwise bare litter, no debris
        for (uint32_t sub = 0; sub < kVernalTufts * tufts; ++sub) propose(AssetKind::Fern, d, point, sub, cx, cy, true);
        continue;
      }
      for (uint32_t sub = 0; sub < tufts; ++sub)
        propose(cover.uniform_double() < fern_share ? AssetKind::Fern : AssetKind::Grass, d, point, sub, cx, cy);
      const uint32_t debris = cover.below(kMaxDebris);
      for (uint32_t sub = tufts; sub < tufts + debris; ++sub) propose(AssetKind::GroundCover, d, point, sub, cx, cy);
    }
  }
  fill_heights(ctx.terrain, solid_x, solid_y, out.solids);
  fill_heights(ctx.terrain, ground_x, ground_y, out.ground);
  return out;
}

}  // namespace silva::world
