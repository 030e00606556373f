#include "world/resolve.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "world/collision_proxy.hpp"

namespace silva::world {

namespace {

constexpr double kTwoPi = 6.283185307179586;

/// State of a solid in the neighbourhood.
enum class State : uint8_t { Neighbour, Kept, Blocked, Moved };

/// A solid in the neighbourhood with its lazily built FCL proxy.
struct Solid {
  const Candidate* c = nullptr;
  Vec3f position;
  State state = State::Neighbour;
  PlacedProxy proxy;  ///< Built on first narrow-phase use.
};

/// Uniform grid of solids over the neighbourhood's footprint (broad phase).
class SolidGrid {
 public:
  /// Grid over [0, extent)^2 (neighbourhood-local coordinates) with square cells.
  SolidGrid(double extent, double cell)
      : cell_(cell), n_(std::max(1, int(std::ceil(extent / cell)))), cells_(size_t(n_) * n_) {}
  /// Adds solid `id` at (x, y).
  void insert(uint32_t id, double x, double y) { cells_[index(cell_of(x), cell_of(y))].push_back(id); }
  /// Removes solid `id`, the last one inserted, at (x, y).
  void remove_last(double x, double y) { cells_[index(cell_of(x), cell_of(y))].pop_back(); }
  /// Calls f(id) for every solid in cells meeting the disc (x, y, r), in cell then insertion order.
  template <class F>
  void query(double x, double y, double r, F&& f) const {
    const int cx0 = cell_of(x - r), cx1 = cell_of(x + r), cy0 = cell_of(y - r), cy1 = cell_of(y + r);
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx)
        for (uint32_t id : cells_[index(cx, cy)]) f(id);
  }

 private:
  int cell_of(double v) const { return std::clamp(int(std::floor(v / cell_)), 0, n_ - 1); }
  size_t index(int cx, int cy) const { return size_t(cy) * n_ + cx; }
  double cell_;
  int n_;
  std::vector<std::vector<uint32_t>> cells_;
};

/// Holds one chunk's resolution state.
class Resolver {
 public:
  Resolver(const WorldContext& ctx, ChunkCoord coord, ResolveStats& stats)
      : ctx_(ctx), coord_(coord), stats_(stats),
        grid_((2 * ctx.neighbour_ring + 1) * ctx.chunk_size(), std::max(1.0, 2.0 * ctx.max_footprint)) {
    origin_x_ = (coord.i - ctx.neighbour_ring) * ctx.chunk_size();
    origin_y_ = (coord.j - ctx.neighbour_ring) * ctx.chunk_size();
  }

  /// Adds a solid candidate to the neighbourhood.
  uint32_t add(const Candidate& c, State state) { return add_at(c, c.position, state); }

  /// True when the proxies of solids a and b collide (narrow phase, higher priority first).
  bool collide(uint32_t a, uint32_t b) {
    ++stats_.narrow_queries;
    const bool a_first = outranks(*solids_[a].c, *solids_[b].c);
    return proxies_collide(proxy(a_first ? a : b), proxy(a_first ? b : a));
  }

  /// Solids whose footprint circle meets the disc (p, r) and that pass `keep`, sorted by priority.
  template <class Keep>
  std::vector<uint32_t> near(const Vec3f& p, float r, Keep&& keep) {
    ++stats_.broad_queries;
    std::vector<uint32_t> out;
    grid_.query(p.x() - origin_x_, p.y() - origin_y_, r + ctx_.max_footprint, [&](uint32_t id) {
      const Solid& s = solids_[id];
      const float reach = r + s.c->footprint;
      if (keep(s) && (s.position.head<2>() - p.head<2>()).squaredNorm() < reach * reach) out.push_back(id);
    });
    std::sort(out.begin(), out.end(), [&](uint32_t a, uint32_t b) { return outranks(*solids_[a].c, *solids_[b].c); });
    return out;
  }

  /// First (highest-priority) solid passing `keep` that collides with solid `id`, or -1.
  template <class Keep>
  int64_t first_hit(uint32_t id, Keep&& keep) {
    for (uint32_t o : near(solids_[id].position, solids_[id].c->footprint, keep))
      if (o != id && collide(id, o)) return o;
    return -1;
  }

  /// Tries periphery spots around `blocker` for blocked solid `id`; on success adds the moved copy.
  bool move(uint32_t id, uint32_t blocker) {
    const Candidate& c = *solids_[id].c;
    const double s = ctx_.chunk_size(), margin = 2.0 * ctx_.max_footprint;
    const double x0 = coord_.i * s + margin, x1 = (coord_.i + 1) * s - margin;
    const double y0 = coord_.j * s + margin, y1 = (coord_.j + 1) * s - margin;
    const Vec3f bp = solids_[blocker].position;
    const double dist = double(c.footprint) + solids_[blocker].c->footprint + kMoveGap;
    Rng rng(uint64_t(ctx_.config.seed), hash_combine(c.chunk_key, c.point), Purpose::ResolveMove);
    const double base = kTwoPi * rng.uniform_double();
    for (int k = 0; k < kMoveTries; ++k) {
      const double th = base + kTwoPi * k / kMoveTries;
      const double x = bp.x() + dist * std::cos(th), y = bp.y() + dist * std::sin(th);
      if (x < x0 || x >= x1 || y < y0 || y >= y1) continue;
      if (on_trail(x, y, c.footprint)) continue;
      const Vec3f p(float(x), float(y), terrain_height(ctx_.terrain, x, y));
      const uint32_t moved = add_at(c, p, State::Moved);
      if (first_hit(moved, [](const Solid& o) { return o.state != State::Blocked; }) < 0) return true;
      remove_last(moved);
    }
    return false;
  }

  /// Solid by id.
  Solid& solid(uint32_t id) { return solids_[id]; }
  /// Number of solids.
  size_t size() const { return solids_.size(); }

 private:
  uint32_t add_at(const Candidate& c, const Vec3f& p, State state) {
    const uint32_t id = uint32_t(solids_.size());
    solids_.push_back(Solid{&c, p, state, {}});
    grid_.insert(id, p.x() - origin_x_, p.y() - origin_y_);
    return id;
  }
  void remove_last(uint32_t id) {
    grid_.remove_last(solids_[id].position.x() - origin_x_, solids_[id].position.y() - origin_y_);
    solids_.pop_back();
  }
  const PlacedProxy& proxy(uint32_t id) {
    Solid& s = solids_[id];
    if (!s.proxy.geometry)
      s.proxy = place_proxy(ctx_.library->assets[s.c->asset].proxy, s.position, s.c->yaw, s.c->scale);
    return s.proxy;
  }
  bool on_trail(double x, double y, float footprint) const {
    if (!ctx_.trail.enabled) return false;
    const double pad = ctx_.trail.corridor_half_width() + footprint;
    const auto segs = trail_segments_near(ctx_.trail, x - pad, y - pad, x + pad, y + pad, 0.0);
    return trail_distance(ctx_.trail, segs, x, y) < pad;
  }

  const WorldContext& ctx_;
  ChunkCoord coord_;
  ResolveStats& stats_;
  SolidGrid grid_;
  double origin_x_ = 0, origin_y_ = 0;
  std::vector<Solid> solids_;
};

/// The final object of a candidate at position p.
Vegetation finalise(const WorldContext& ctx, const Candidate& c, const Vec3f& p, Placement placement) {
  Vegetation v;
  v.asset = c.asset;
  v.role = ctx.library->assets[c.asset].role;
  v.placement = placement;
  v.position = p;
  v.yaw = c.yaw;
  v.scale = c.scale;
  return v;
}

}  // namespace

std::vector<Vegetation> resolve_chunk(const WorldContext& ctx, ChunkCoord coord, const ChunkCandidates& own,
                                      const CandidateLookup& neighbours, ResolveStats& stats) {
  Resolver r(ctx, coord, stats);
  const int ring = ctx.neighbour_ring;
  for (int dj = -ring; dj <= ring; ++dj)
    for (int di = -ring; di <= ring; ++di)
      if (di != 0 || dj != 0)
        for (const Candidate& c : neighbours(ChunkCoord{coord.i + di, coord.j + dj}).solids) r.add(c, State::Neighbour);
  const uint32_t own_begin = uint32_t(r.size());
  for (const Candidate& c : own.solids) r.add(c, State::Kept);
  const uint32_t own_end = uint32_t(r.size());

  // 1. A candidate is blocked by any higher-priority candidate (own or neighbour) it collides with.
  std::vector<std::pair<uint32_t, uint32_t>> blocked;  // (solid, blocker)
  for (uint32_t id = own_begin; id < own_end; ++id) {
    const Candidate& c = *r.solid(id).c;
    const int64_t hit = r.first_hit(id, [&](const Solid& o) { return outranks(*o.c, c); });
    if (hit >= 0) blocked.emplace_back(id, uint32_t(hit));
  }
  for (auto [id, blocker] : blocked) r.solid(id).state = State::Blocked;
  // 2. Blocked candidates move in priority order, or are dropped.
  std::sort(blocked.begin(), blocked.end(),
            [&](auto a, auto b) { return outranks(*r.solid(a.first).c, *r.solid(b.first).c); });
  for (auto [id, blocker] : blocked) {
    if (r.move(id, blocker))
      ++stats.adjusted;
    else
      ++stats.dropped;
  }
  // 3. Final objects in (point, sub) order: kept, moved, then surviving ground vegetation.
  std::vector<std::pair<const Candidate*, uint32_t>> order;  // (candidate, solid id or UINT32_MAX)
  for (uint32_t id = own_begin; id < r.size(); ++id)
    if (r.solid(id).state == State::Kept || r.solid(id).state == State::Moved) order.emplace_back(r.solid(id).c, id);
  for (const Candidate& g : own.ground) {
    const auto hits = r.near(g.position, g.footprint, [](const Solid& o) { return o.state != State::Blocked; });
    if (hits.empty())
      order.emplace_back(&g, UINT32_MAX);
    else
      ++stats.ground_dropped;
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first->point != b.first->point ? a.first->point < b.first->point : a.first->sub < b.first->sub;
  });
  std::vector<Vegetation> out;
  out.reserve(order.size());
  for (const auto& [c, id] : order) {
    if (id == UINT32_MAX)
      out.push_back(finalise(ctx, *c, c->position, Placement::Correct));
    else
      out.push_back(finalise(ctx, *c, r.solid(id).position,
                             r.solid(id).state == State::Moved ? Placement::Adjusted : Placement::Correct));
  }
  return out;
}

}  // namespace silva::world
