#include "bench/harness/profile_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace silva::bench {

double nearest_rank(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  return sorted[size_t(std::floor(q * double(sorted.size() - 1)))];
}

std::optional<NearestStats> nearest_neighbours(const std::vector<Eigen::Vector2d>& points) {
  const size_t n = points.size();
  if (n < 2) return std::nullopt;
  Eigen::Vector2d lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double area = std::max(1.0, (hi.x() - lo.x()) * (hi.y() - lo.y()));
  const double cell = std::max(0.25, std::sqrt(area / double(n)));
  const int nx = int((hi.x() - lo.x()) / cell) + 1, ny = int((hi.y() - lo.y()) / cell) + 1;
  // Points bucketed by cell (counting sort): start[c] .. start[c + 1] in `order`.
  std::vector<uint32_t> start(size_t(nx) * ny + 1, 0), order(n);
  std::vector<uint32_t> cell_of(n);
  for (size_t k = 0; k < n; ++k) {
    const int cx = int((points[k].x() - lo.x()) / cell), cy = int((points[k].y() - lo.y()) / cell);
    cell_of[k] = uint32_t(cy * nx + cx);
    ++start[cell_of[k] + 1];
  }
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t k = 0; k < n; ++k) order[fill[cell_of[k]]++] = uint32_t(k);

  std::vector<double> nearest(n);
  for (size_t k = 0; k < n; ++k) {
    const int cx = int(cell_of[k] % uint32_t(nx)), cy = int(cell_of[k] / uint32_t(nx));
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < std::max(nx, ny); ++r) {
      for (int y = cy - r; y <= cy + r; ++y) {
        if (y < 0 || y >= ny) continue;
        const bool edge_row = y == cy - r || y == cy + r;
        for (int x = cx - r; x <= cx + r; x += edge_row ? 1 : 2 * std::max(r, 1)) {
          if (x < 0 || x >= nx) continue;
          const size_t c = size_t(y) * nx + x;
          for (uint32_t s = start[c]; s < start[c + 1]; ++s)
            if (order[s] != k) best = std::min(best, (points[order[s]] - points[k]).norm());
        }
      }
      if (r * cell >= best) break;  // every point of ring r + 1 is at least r cells away
    }
    nearest[k] = best;
  }
  std::sort(nearest.begin(), nearest.end());
  return NearestStats{nearest.front(), nearest_rank(nearest, 0.10), nearest_rank(nearest, 0.5),
                      nearest_rank(nearest, 0.90)};
}

CoverGrid::CoverGrid(int i0, int j0, int i1, int j1, double chunk_size, double cell, std::vector<bool> inside)
    : x0_(i0 * chunk_size),
      y0_(j0 * chunk_size),
      cell_(cell),
      chunk_size_(chunk_size),
      i0_(i0),
      j0_(j0),
      chunks_x_(i1 - i0 + 1),
      chunks_y_(j1 - j0 + 1),
      nx_(int(std::lround(chunks_x_ * chunk_size / cell))),
      ny_(int(std::lround(chunks_y_ * chunk_size / cell))),
      inside_(std::move(inside)),
      bits_(size_t(nx_) * ny_, 0) {
  const int per_chunk = int(std::lround(chunk_size / cell));
  for (bool in : inside_) counted_ += in ? uint64_t(per_chunk) * per_chunk : 0;
}

void CoverGrid::add(const Disc& disc, int layer) {
  const uint8_t bit = uint8_t(1u << layer);
  const int x_lo = std::max(0, int(std::floor((disc.centre.x() - disc.radius - x0_) / cell_)));
  const int x_hi = std::min(nx_ - 1, int(std::floor((disc.centre.x() + disc.radius - x0_) / cell_)));
  const int y_lo = std::max(0, int(std::floor((disc.centre.y() - disc.radius - y0_) / cell_)));
  const int y_hi = std::min(ny_ - 1, int(std::floor((disc.centre.y() + disc.radius - y0_) / cell_)));
  const double r2 = disc.radius * disc.radius;
  for (int y = y_lo; y <= y_hi; ++y) {
    const double dy = y0_ + (y + 0.5) * cell_ - disc.centre.y();
    for (int x = x_lo; x <= x_hi; ++x) {
      const double dx = x0_ + (x + 0.5) * cell_ - disc.centre.x();
      if (dx * dx + dy * dy <= r2) bits_[size_t(y) * nx_ + x] |= bit;
    }
  }
}

double CoverGrid::percent(int layer) const {
  if (counted_ == 0) return 0;
  const uint8_t bit = uint8_t(1u << layer);
  uint64_t covered = 0;
  for (int y = 0; y < ny_; ++y) {
    const int cj = std::min(chunks_y_ - 1, int((y + 0.5) * cell_ / chunk_size_));
    for (int x = 0; x < nx_; ++x) {
      const int ci = std::min(chunks_x_ - 1, int((x + 0.5) * cell_ / chunk_size_));
      if (inside_[size_t(cj) * chunks_x_ + ci] && (bits_[size_t(y) * nx_ + x] & bit)) ++covered;
    }
  }
  return 100.0 * double(covered) / double(counted_);
}

double crown_radius(const assets::Asset& asset) {
  if (asset.lods().empty()) return 0;
  const Mesh& m = asset.lods()[0];
  const bool has_canopy = std::any_of(m.parts.begin(), m.parts.end(), [](const MeshPart& p) { return p.role == Role::TreeCanopy; });
  double r = 0;
  for (const MeshPart& p : m.parts) {
    if (has_canopy && p.role != Role::TreeCanopy) continue;
    for (uint32_t k = p.first_index; k < p.first_index + p.index_count; ++k) {
      const auto& v = m.positions[m.indices[k]];
      r = std::max(r, std::hypot(double(v.x()), double(v.y())));
    }
  }
  return r;
}

}  // namespace silva::bench
