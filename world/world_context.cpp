#include "world/world_context.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "world/class_mix.hpp"

namespace silva::world {

namespace {

/// Throws unless `whole` is a positive whole multiple of `part`.
void require_multiple(double whole, double part, const char* part_key) {
  const double q = whole / part;
  if (!(part > 0) || !(q >= 1) || std::abs(q - std::round(q)) > 1e-9)
    throw InputError("terrain.chunk_size = " + std::to_string(whole) + " must be a whole multiple of " + part_key +
                     " = " + std::to_string(part));
}

}  // namespace

WorldContext make_world_context(const Config& cfg, const assets::AssetLibrary& library) {
  require_multiple(cfg.terrain.chunk_size, cfg.terrain.vertex_spacing, "terrain.vertex_spacing");
  require_multiple(cfg.terrain.chunk_size, cfg.vegetation.grid_spacing, "vegetation.grid_spacing");
  WorldContext ctx;
  ctx.config = cfg;
  ctx.library = &library;
  ctx.terrain = make_terrain_field(cfg);
  ctx.trail = build_trail(cfg, ctx.terrain);
  ctx.forest = &forest_type_of(cfg.vegetation.forest_type, uint64_t(cfg.seed));
  ctx.trail_surface = trail_surface_of(cfg.trail.surface, uint64_t(cfg.seed));
  parse_season(cfg.vegetation.season, ctx.season);  // the schema allows only the season names
  ctx.stands = make_species_stands(library, uint64_t(cfg.seed), *ctx.forest, ctx.season);
  ctx.footprint.resize(library.assets.size());
  for (size_t a = 0; a < library.assets.size(); ++a) {
    const auto& asset = library.assets[a];
    const bool solid = is_solid(asset.kind) && asset.proxy.shape != assets::CollisionProxy::Shape::None;
    ctx.footprint[a] = solid ? asset.proxy.footprint_radius() : kGroundFootprint;
    if (solid) ctx.max_footprint = std::max(ctx.max_footprint, ctx.footprint[a] * kMaxScale);
  }
  ctx.neighbour_ring = std::max(1, int(std::ceil(2.0 * ctx.max_footprint / cfg.terrain.chunk_size)));
  return ctx;
}

}  // namespace silva::world
