#include "pipeline/config/cost_estimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/input_limits.hpp"

namespace silva::pipeline {

namespace {

constexpr double kPi = 3.14159265358979;
/// Bytes per terrain vertex of a generated chunk (position, normal, uv, its share of the indices
/// and of the LOD copies): `silva world` peak memory grew 3.4 MB per chunk from vertex_spacing 0.5 to 0.125.
constexpr double kBytesPerVertex = 60;
/// Bytes per placement point of a generated chunk (placed objects, proxies): 1.45 MB per chunk from
/// grid_spacing 2 to 0.5.
constexpr double kBytesPerPoint = 400;

/// Memory one chunk takes.
double chunk_bytes(const Config& c) {
  const double vertices = std::pow(c.terrain.chunk_size / c.terrain.vertex_spacing + 1, 2);
  const double points = std::pow(c.terrain.chunk_size / c.vegetation.grid_spacing, 2);
  return vertices * kBytesPerVertex + points * kBytesPerPoint;
}

/// Chunks of side s overlapping a disc of radius r.
double disc_chunks(double r, double s) { return kPi * std::pow(r + s, 2) / (s * s); }

double machine_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0.0;
}

CostEstimate estimate_for(const Config& c, double chunks, double view_chunks) {
  CostEstimate e;
  e.chunks = chunks;
  e.bytes = chunks * chunk_bytes(c);
  e.points_per_frame = view_chunks * std::pow(c.terrain.chunk_size / c.vegetation.grid_spacing, 2);
  e.machine_bytes = machine_bytes();
  return e;
}

/// "12.3 GB"
std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

}  // namespace

CostEstimate estimate_generate_cost(const Config& c) {
  const double s = c.terrain.chunk_size;
  // The far plane's footprint: a triangle of depth far and half-width far * tan(fov / 2) (capped
  // at 80 degrees), widened by a chunk on every side.
  const double half_fov = std::min(c.camera.fov_deg * 0.5, 80.0) * kPi / 180.0;
  const double far = c.camera.far + s;
  const double view = far * far * std::tan(half_fov) / (s * s) + 4 * far / s;
  const double cache = std::max(256.0, disc_chunks(c.world.render_distance, s));
  return estimate_for(c, std::max(view, cache), view);
}

CostEstimate estimate_world_cost(const Config& c, std::optional<double> radius) {
  const double s = c.terrain.chunk_size;
  const double chunks = radius ? disc_chunks(*radius, s)
                               : std::pow(c.world.extent + 2 * c.world.render_distance + s, 2) / (s * s);
  return estimate_for(c, chunks, 0);  // a world is built once: only its memory is bounded
}

void check_cost(const CostEstimate& e, bool force, const std::string& what, bool can_force) {
  if (force) return;
  const bool memory = e.machine_bytes > 0 && e.bytes > limits::kMaxMemoryShare * e.machine_bytes;
  const bool work = e.points_per_frame > limits::kMaxPlacementPointsPerFrame;
  if (!memory && !work) return;
  char numbers[256];
  std::snprintf(numbers, sizeof numbers, "about %.3g chunks at once, %s of memory (this machine has %s)", e.chunks,
                gigabytes(e.bytes).c_str(), gigabytes(e.machine_bytes).c_str());
  char points[128];
  std::snprintf(points, sizeof points, " and %.3g placement points per frame (at most %.3g)", e.points_per_frame,
                limits::kMaxPlacementPointsPerFrame);
  throw InputError(what + ": this config needs " + numbers + (work ? points : "") +
                   "; lower camera.far, world.render_distance or terrain.chunk_size, raise terrain.vertex_spacing or "
                   "vegetation.grid_spacing" + (can_force ? ", or pass --force to run it anyway" : ""));
}

}  // namespace silva::pipeline
