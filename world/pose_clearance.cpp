#include "world/pose_clearance.hpp"

#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>

#include <algorithm>
#include <cmath>

#include "world/chunk_regions.hpp"
#include "world/class_mix.hpp"
#include "world/collision_proxy.hpp"
#include "world/terrain.hpp"

namespace silva::world {

namespace {

/// Height bands of a crown profile.
constexpr int kCrownBands = 16;

/// The profile of one mesh's canopy parts.
CrownProfile crown_of(const Mesh& m) {
  CrownProfile p;
  float lo = INFINITY, hi = -INFINITY;
  auto each_canopy_vertex = [&m](auto&& f) {
    for (const MeshPart& part : m.parts)
      if (part.role == Role::TreeCanopy)
        for (uint32_t i = part.first_index; i < part.first_index + part.index_count; ++i) f(m.positions[m.indices[i]]);
  };
  each_canopy_vertex([&](const Vec3f& v) { lo = std::min(lo, v.z()), hi = std::max(hi, v.z()); });
  if (!(lo <= hi)) return p;
  p.z_min = lo;
  p.band = std::max((hi - lo) / float(kCrownBands), 1e-3f);
  p.radius.assign(kCrownBands, 0.0f);
  each_canopy_vertex([&](const Vec3f& v) {
    const int b = std::clamp(int((v.z() - lo) / p.band), 0, kCrownBands - 1);
    p.radius[size_t(b)] = std::max(p.radius[size_t(b)], std::hypot(v.x(), v.y()));
  });
  return p;
}

}  // namespace

CrownProfiles::CrownProfiles(const assets::AssetLibrary& library)
    : library_(&library),
      once_(std::make_unique<std::once_flag[]>(library.assets.size())),
      profiles_(library.assets.size()) {}

const CrownProfile& CrownProfiles::operator[](size_t asset) const {
  std::call_once(once_[asset], [&] {
    const auto& lods = library_->assets[asset].lods();
    if (!lods.empty()) profiles_[asset] = crown_of(lods[0]);
  });
  return profiles_[asset];
}

double ClearanceProbe::reach(const WorldContext& ctx, double radius) {
  const Config& c = ctx.config;
  return radius + std::max(c.captures.clearance + ctx.max_footprint,
                           std::max(c.captures.aerial_crown_clearance, c.captures.ground_crown_clearance) +
                               kMaxCrownReach * kMaxScale);
}

ClearanceProbe::ClearanceProbe(const WorldContext& ctx, const CrownProfiles& crowns,
                               const std::vector<std::shared_ptr<const ChunkContent>>& chunks, double x, double y,
                               double radius)
    : ctx_(ctx), crowns_(crowns) {
  const double limit = reach(ctx, radius);
  for (const auto& chunk : chunks)
    for (const Vegetation& v : chunk->objects) {
      if (std::hypot(v.position.x() - x, v.position.y() - y) > limit) continue;
      if (ctx.library->assets[v.asset].proxy.shape != assets::CollisionProxy::Shape::None) solids_.push_back(v);
      const AssetKind kind = ctx.library->assets[v.asset].kind;
      if (kind == AssetKind::ConiferTree || kind == AssetKind::BroadleafTree) crowned_.push_back(v);
    }
}

ClearanceProbe ClearanceProbe::around(const WorldContext& ctx, ChunkSource& chunks, const CrownProfiles& crowns,
                                      double x, double y, double radius) {
  return ClearanceProbe(ctx, crowns, chunks.require(ctx, chunks_in_disc(x, y, reach(ctx, radius), ctx.chunk_size())), x,
                        y, radius);
}

double ClearanceProbe::canopy_top(double x, double y, double margin) const {
  double top = -INFINITY;
  for (const Vegetation& v : crowned_) {
    const CrownProfile& p = crowns_[v.asset];
    const double s = v.scale, d = std::hypot(x - v.position.x(), y - v.position.y());
    for (size_t b = 0; b < p.radius.size(); ++b)
      if (d <= s * p.radius[b] + margin)
        top = std::max(top, v.position.z() + s * (p.z_min + double(p.band) * double(b + 1)));
  }
  return top;
}

bool ClearanceProbe::near_crown(const Vegetation& v, const Vec3d& eye, double r) const {
  const CrownProfile& p = crowns_[v.asset];
  const double s = v.scale;
  const double d = std::hypot(eye.x() - v.position.x(), eye.y() - v.position.y());
  const double z = eye.z() - v.position.z();
  for (size_t b = 0; b < p.radius.size(); ++b) {
    const double z0 = s * (p.z_min + double(p.band) * double(b)), z1 = z0 + s * p.band;
    const double dz = z < z0 ? z0 - z : (z > z1 ? z - z1 : 0.0);
    const double dr = std::max(0.0, d - s * p.radius[b]);
    if (std::hypot(dz, dr) < r) return true;
  }
  return false;
}

bool ClearanceProbe::clear(const Vec3d& eye, bool aerial) const {
  if (!solids_clear(eye, aerial)) return false;
  const CapturesConfig& c = ctx_.config.captures;
  const double crown = aerial ? c.aerial_crown_clearance : c.ground_crown_clearance;
  if (crown > 0.0)
    for (const Vegetation& v : crowned_)
      if (near_crown(v, eye, crown)) return false;
  return true;
}

bool ClearanceProbe::column_clear(const Vec3d& eye) const { return solids_clear(eye, false); }

bool ClearanceProbe::solids_clear(const Vec3d& eye, bool aerial) const {
  const Config& c = ctx_.config;
  const float r = float(std::max(c.captures.clearance, 1e-3));
  PlacedProxy camera;
  if (aerial) {
    camera.geometry = std::make_shared<fcl::Spheref>(r);
    camera.transform.translation() = eye.cast<float>();
  } else {
    const float ground = terrain_height(ctx_.terrain, eye.x(), eye.y());
    const float column = std::max(float(eye.z()) - ground, 0.1f);
    camera.geometry = std::make_shared<fcl::Cylinderf>(r, column);
    camera.transform.translation() = fcl::Vector3f(float(eye.x()), float(eye.y()), ground + 0.5f * column);
  }
  return touched_solid(camera, eye, r + ctx_.max_footprint) == nullptr;
}

const Vegetation* ClearanceProbe::solid_at(const Vec3d& point, double radius) const {
  PlacedProxy sphere;
  sphere.geometry = std::make_shared<fcl::Spheref>(float(radius));
  sphere.transform.translation() = point.cast<float>();
  return touched_solid(sphere, point, radius + ctx_.max_footprint);
}

const Vegetation* ClearanceProbe::touched_solid(const PlacedProxy& shape, const Vec3d& centre, double reach) const {
  for (const Vegetation& v : solids_) {
    if (std::hypot(v.position.x() - centre.x(), v.position.y() - centre.y()) > reach) continue;
    const auto& proxy = ctx_.library->assets[v.asset].proxy;
    if (proxies_collide(shape, place_proxy(proxy, v.position, v.yaw, v.scale))) return &v;
  }
  return nullptr;
}

}  // namespace silva::world
