// `silva verify`'s per-pixel comparison (see verify_compare.hpp).
#include "app/commands/verify/verify_compare.hpp"

#include <algorithm>
#include <cmath>

namespace silva::app {

namespace {

/// Depth the PNG clamps to (65.535 m): a ray at or beyond it agrees with a clamped pixel.
constexpr double kDepthPngMax = 65.535;

/// The bin of value v.
int bin_of(double v) {
  if (!(v >= ErrorHistogram::kLowest)) return 0;
  const int b = 1 + int(std::floor(std::log10(v / ErrorHistogram::kLowest) * ErrorHistogram::kPerDecade));
  return std::min(b, int(ErrorHistogram().bins.size()) - 1);
}

/// Upper edge of bin b.
double upper_edge(int b) { return ErrorHistogram::kLowest * std::pow(10.0, double(b) / ErrorHistogram::kPerDecade); }

/// A disagreement and how bad it is (interior class mismatches first, then by relative depth error).
struct Candidate {
  PixelDisagreement pixel;
  double severity = 0;
};

}  // namespace

void ErrorHistogram::add(double value) {
  ++bins[size_t(bin_of(value))];
  ++count;
  max = std::max(max, value);
}

void ErrorHistogram::merge(const ErrorHistogram& other) {
  for (size_t b = 0; b < bins.size(); ++b) bins[b] += other.bins[b];
  count += other.count;
  max = std::max(max, other.max);
}

double ErrorHistogram::quantile(double q) const {
  if (count == 0) return 0;
  const uint64_t rank = std::max<uint64_t>(1, uint64_t(std::ceil(q * double(count))));
  uint64_t seen = 0;
  for (size_t b = 0; b < bins.size(); ++b) {
    seen += bins[b];
    if (seen >= rank) return std::min(max, b + 1 == bins.size() ? max : upper_edge(int(b)));
  }
  return max;
}

uint64_t ErrorHistogram::at_most(double limit) const {
  uint64_t n = 0;
  for (int b = 0; b <= bin_of(limit); ++b) n += bins[size_t(b)];
  return n;
}

std::pair<uint64_t, uint64_t> ClassCounts::total() const {
  uint64_t p = 0, a = 0;
  for (size_t c = 0; c < pixels.size(); ++c) p += pixels[c], a += agree[c];
  return {p, a};
}

void VerifyTally::merge(const VerifyTally& o) {
  for (size_t c = 0; c < 256; ++c) {
    interior.pixels[c] += o.interior.pixels[c];
    interior.agree[c] += o.interior.agree[c];
    silhouette.pixels[c] += o.silhouette.pixels[c];
    silhouette.agree[c] += o.silhouette.agree[c];
    depth_hit_by_class[c] += o.depth_hit_by_class[c];
    depth_within_by_class[c] += o.depth_within_by_class[c];
  }
  instance_pixels += o.instance_pixels;
  instance_agree += o.instance_agree;
  depth_hit += o.depth_hit;
  depth_within += o.depth_within;
  depth_only_file += o.depth_only_file;
  depth_only_ray += o.depth_only_ray;
  depth_error.merge(o.depth_error);
  normal_error_deg.merge(o.normal_error_deg);
  for (const auto& [k, n] : o.confusion) confusion[k] += n;
}

bool interior_pixel(std::span<const uint8_t> semantic, int width, int height, uint32_t p) {
  const int x = int(p % uint32_t(width)), y = int(p / uint32_t(width));
  const uint8_t c = semantic[p];
  for (int yy = std::max(0, y - 1); yy <= std::min(height - 1, y + 1); ++yy)
    for (int xx = std::max(0, x - 1); xx <= std::min(width - 1, x + 1); ++xx)
      if (semantic[size_t(yy) * size_t(width) + size_t(xx)] != c) return false;
  return true;
}

VerifyTally compare_frame(const FrameTruth& truth, std::span<const uint32_t> pixels,
                          std::span<const raycast::RayHit> hits, const Ontology& ontology,
                          const CompareOptions& options) {
  VerifyTally t;
  std::vector<Candidate> bad;
  const uint8_t background = ontology.id(Role::Background);
  for (size_t k = 0; k < pixels.size(); ++k) {
    const uint32_t p = pixels[k];
    const raycast::RayHit& h = hits[k];
    const uint8_t file_class = truth.semantic[p];
    const uint8_t ray_class = h.hit ? ontology.id(h.role) : background;
    const bool interior = interior_pixel(truth.semantic, truth.width, truth.height, p);
    ClassCounts& counts = interior ? t.interior : t.silhouette;
    ++counts.pixels[file_class];
    counts.agree[file_class] += file_class == ray_class;
    if (interior && file_class != ray_class) ++t.confusion[{file_class, ray_class}];
    if (interior && !truth.instance.empty()) {
      const uint32_t want = h.hit && role_has_instances(h.role) ? h.instance_id : 0;
      ++t.instance_pixels;
      t.instance_agree += truth.instance[p] == want;
    }
    const double d = truth.depth[p], z = h.hit ? double(h.t) : 0.0;
    bool depth_ok = true;
    double rel = 0;
    if (d > 0 || z > 0) {
      ++t.depth_hit;
      ++t.depth_hit_by_class[file_class];
      if (d > 0 && z > 0) {
        rel = std::abs(z - d) / d;
        t.depth_error.add(rel);
        const bool clamped = truth.depth_step > 0 && d >= kDepthPngMax - 0.5 * truth.depth_step && z >= d;
        depth_ok = clamped || std::abs(z - d) <= options.depth_tolerance * d + 0.5 * truth.depth_step;
      } else {
        depth_ok = false;
        rel = std::numeric_limits<double>::infinity();
        ++(d > 0 ? t.depth_only_file : t.depth_only_ray);
      }
      t.depth_within += depth_ok;
      t.depth_within_by_class[file_class] += depth_ok;
    }
    if (depth_ok && d > 0 && z > 0 && file_class == ray_class && !truth.normal.empty() &&
        truth.normal[p].squaredNorm() > 0) {
      const double c = std::clamp(double(truth.normal[p].normalized().dot(h.normal)), -1.0, 1.0);
      t.normal_error_deg.add(std::acos(c) * 180.0 / 3.14159265358979323846);
    }
    const bool class_bad = interior && file_class != ray_class;
    if (class_bad || !depth_ok) {
      const int x = int(p % uint32_t(truth.width)), y = int(p / uint32_t(truth.width));
      bad.push_back({{x, y, file_class, ray_class, float(d), float(z), interior},
                     (class_bad ? 1e300 : 0.0) + std::min(rel, 1e299)});
    }
  }
  const size_t keep = std::min(options.examples, bad.size());
  std::partial_sort(bad.begin(), bad.begin() + ptrdiff_t(keep), bad.end(),
                    [](const Candidate& a, const Candidate& b) {
                      if (a.severity != b.severity) return a.severity > b.severity;
                      return a.pixel.y != b.pixel.y ? a.pixel.y < b.pixel.y : a.pixel.x < b.pixel.x;
                    });
  for (size_t i = 0; i < keep; ++i) t.examples.push_back(bad[i].pixel);
  return t;
}

}  // namespace silva::app
