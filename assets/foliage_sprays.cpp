#include "assets/foliage_sprays.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <vector>

#include "core/rng.hpp"

namespace silva::assets {

namespace {

/// Texels a leaf is at least long (up to the largest mask size).
constexpr float kLeafTexels = 12.0f;
/// Smallest and largest mask side, texels.
constexpr int kMinSpraySize = 256, kMaxSpraySize = 1024;
/// Twig half-width at the spray's base, metres (thinning towards the tips and down the orders).
constexpr float kTwigHalfWidth = 0.0025f;
/// Half-width of a bare twig per unit of its length (a 1 m branch is 2 cm thick at its base).
constexpr float kBareTwigTaper = 0.01f;
/// Deepest order of side twigs.
constexpr int kMaxTwigOrder = 3;
/// Bisection steps towards a spray's coverage.
constexpr int kCoverageSteps = 7;

/// Draws one spray's strokes in mask units (leaf length `L` in them).
class SprayDrawer {
 public:
  SprayDrawer(const SprayLeaf& leaf, float L, float texel, float side_m, Rng& rng, std::vector<Stroke>& out)
      : leaf_(leaf), L_(L), texel_(texel), side_m_(side_m), rng_(rng), out_(out) {}

  /// A twig from `a` at `deg` (0 = up the mask), at most `len` long, of order `order`: its stroke,
  /// its side twigs while it is long enough to carry them, and its leaves.
  void twig(const Vec2f& a, float deg, float len, int order) {
    len = std::min(len, room(a, deg));
    if (len < std::min(1.5f * L_, 0.3f)) return;
    const Vec2f b = stroke_towards(a, deg, len);
    float w = std::max(kTwigHalfWidth / side_m_ / float(1 + order), 0.6f * texel_);
    if (leaf_.arrangement == SprayLeaf::Arrangement::Bare) w = std::max(w, kBareTwigTaper * len);  // thicker where longer
    out_.push_back({a, b, w, std::max(0.4f * w, 0.5f * texel_), Stroke::Shape::Tapered});
    const float gap = leaf_.twig_gap * L_;
    if (order < kMaxTwigOrder && len > 3.0f * gap) {
      float side = rng_.uniform() < 0.5f ? -1.0f : 1.0f;
      for (float t = 0.12f * len; t < 0.9f * len; t += gap * rng_.range(0.85f, 1.15f), side = -side) {
        const float f = t / len;
        const float child = 0.55f * len * std::pow(1.0f - f, 0.7f);
        twig(stroke_towards(a, deg, t), deg + side * rng_.range(45.0f, 60.0f), child, order + 1);
      }
    }
    if (leaf_.arrangement != SprayLeaf::Arrangement::Bare) leaves_along(a, deg, len);
  }

 private:
  /// Longest length a twig from `a` at `deg` may have so that it and its leaves stay in the mask.
  float room(const Vec2f& a, float deg) const {
    const Vec2f d = stroke_towards(Vec2f::Zero(), deg, 1.0f);
    const float margin = std::min(1.05f * L_, 0.25f);
    const float lo = 0.01f + margin, hi = 0.99f - margin;
    float t = 2.0f;
    for (int k = 0; k < 2; ++k) {
      if (d[k] > 1e-6f) t = std::min(t, (hi - a[k]) / d[k]);
      if (d[k] < -1e-6f) t = std::min(t, (lo - a[k]) / d[k]);
    }
    return std::max(t, 0.0f);
  }

  /// One leaf (or needle) from `base` at `deg`, `len` long, with its own brightness (alpha 128..254).
  void leaf(const Vec2f& base, float deg, float len) {
    const float half = std::max(leaf_.half_width * len, 0.55f * texel_);
    const size_t first = out_.size();
    const Vec2f tip = stroke_towards(base, deg, len);
    if (leaf_.lobes > 0)
      add_leaf_strokes(out_, base, deg, len, half, leaf_.lobes);
    else if (leaf_.shape == Stroke::Shape::Tapered)
      out_.push_back({base, tip, half, std::max(0.4f * half, 0.5f * texel_), Stroke::Shape::Tapered});
    else
      out_.push_back({base, tip, half, 0, leaf_.shape});
    const auto alpha = uint8_t(128 + rng_.next_u64() % 127);
    for (size_t k = first; k < out_.size(); ++k) out_[k].alpha = alpha;
  }

  /// The leaves of a twig from `a` at `deg`, `len` long, from leaf_.from of its length to its tip.
  void leaves_along(const Vec2f& a, float deg, float len) {
    float side = rng_.uniform() < 0.5f ? -1.0f : 1.0f;
    for (float t = leaf_.from * len; t <= len; t += leaf_.spacing * L_ * rng_.range(0.8f, 1.2f), side = -side) {
      const Vec2f p = stroke_towards(a, deg, t);
      const float l = L_ * rng_.range(0.85f, 1.15f);
      const float turn = leaf_.angle_deg + rng_.range(-10.0f, 10.0f);
      switch (leaf_.arrangement) {
        case SprayLeaf::Arrangement::Alternate:  // a short petiole, then the blade
          leaf(stroke_towards(p, deg + side * turn, 0.1f * l), deg + side * turn, l);
          break;
        case SprayLeaf::Arrangement::Brush:
          leaf(p, deg + turn, l);
          leaf(p, deg - turn + rng_.range(-6.0f, 6.0f), l * rng_.range(0.9f, 1.1f));
          break;
        case SprayLeaf::Arrangement::Bare: break;
        case SprayLeaf::Arrangement::Rosette: {
          const Vec2f shoot = stroke_towards(p, deg + side * turn, 0.12f * l);
          for (int k = 0; k < 11; ++k)
            leaf(shoot, deg + side * turn + rng_.range(-8.0f, 8.0f) - 70.0f + 14.0f * float(k), l * rng_.range(0.6f, 1.0f));
          break;
        }
      }
    }
  }

  const SprayLeaf& leaf_;
  float L_, texel_, side_m_;
  Rng& rng_;
  std::vector<Stroke>& out_;
};

/// Opaque share of a mask.
double coverage(const AlphaMask& m) {
  return double(std::count_if(m.alpha.begin(), m.alpha.end(), [](uint8_t a) { return a >= 128; })) /
         double(m.alpha.size());
}

/// Draws every class of `leaf`'s spray.
std::array<std::shared_ptr<const AlphaMask>, kSprayClasses> draw_family(const SprayLeaf& leaf, uint64_t seed) {
  std::array<std::shared_ptr<const AlphaMask>, kSprayClasses> out;
  for (int k = 0; k < kSprayClasses; ++k) out[size_t(k)] = draw_spray(leaf, kSprayClassSide * float(1 << k), seed);
  return out;
}

/// The family of `leaf` (jitter seed `seed`): every class drawn on first use, then shared.
template <const SprayLeaf& leaf, uint64_t seed>
std::shared_ptr<const AlphaMask> family(float card_side_m) {
  static const auto masks = draw_family(leaf, seed);
  return masks[size_t(spray_class(card_side_m))];
}

using enum SprayLeaf::Arrangement;
using Shape = Stroke::Shape;

constexpr SprayLeaf kSpruce{.length_m = 0.018f, .half_width = 0.05f, .angle_deg = 55.0f, .spacing = 0.3f, .from = 0.0f,
                            .shape = Shape::Tapered, .arrangement = Brush, .twig_gap = 2.8f, .coverage = 0.26f};
constexpr SprayLeaf kPine{.length_m = 0.05f, .half_width = 0.03f, .angle_deg = 35.0f, .spacing = 0.06f, .from = 0.4f,
                          .shape = Shape::Tapered, .arrangement = Brush, .twig_gap = 2.0f, .coverage = 0.18f};
constexpr SprayLeaf kLarch{.length_m = 0.03f, .half_width = 0.04f, .angle_deg = 60.0f, .spacing = 0.6f, .from = 0.1f,
                           .shape = Shape::Tapered, .arrangement = Rosette, .twig_gap = 2.2f, .coverage = 0.15f};
constexpr SprayLeaf kBeech{.length_m = 0.075f, .half_width = 0.3f, .angle_deg = 60.0f, .spacing = 0.45f, .from = 0.1f,
                           .shape = Shape::Round, .twig_gap = 1.8f, .coverage = 0.37f};
constexpr SprayLeaf kBirch{.length_m = 0.05f, .half_width = 0.33f, .angle_deg = 55.0f, .spacing = 0.55f, .from = 0.1f,
                           .shape = Shape::Pointed, .twig_gap = 2.0f, .coverage = 0.21f};
constexpr SprayLeaf kTwigs{.length_m = 0.02f, .angle_deg = 50.0f, .arrangement = Bare, .twig_gap = 1.6f, .coverage = 0.1f};
constexpr SprayLeaf kOak{.length_m = 0.10f, .half_width = 0.28f, .angle_deg = 50.0f, .spacing = 0.35f, .from = 0.3f,
                         .lobes = 3, .shape = Shape::Round, .twig_gap = 1.8f, .coverage = 0.25f};

}  // namespace

int spray_class(float card_side_m) {
  const float k = std::round(std::log2(std::max(card_side_m, 1e-3f) / kSprayClassSide));
  return std::clamp(int(k), 0, kSprayClasses - 1);
}

std::shared_ptr<const AlphaMask> draw_spray(const SprayLeaf& leaf, float card_side_m, uint64_t seed) {
  const float L = leaf.length_m / card_side_m;
  const int size = std::clamp(int(std::bit_ceil(unsigned(std::ceil(kLeafTexels / L)))), kMinSpraySize, kMaxSpraySize);
  const auto draw = [&](double scale, int texels) {
    SprayLeaf scaled = leaf;
    scaled.spacing *= float(scale);
    scaled.twig_gap *= float(scale);
    Rng rng(seed, uint64_t(spray_class(card_side_m)), Purpose::AssetShape);
    std::vector<Stroke> strokes;
    SprayDrawer(scaled, L, 1.0f / float(size), card_side_m, rng, strokes)
        .twig({0.5f, 0.995f}, rng.range(-4.0f, 4.0f), 0.95f, 0);
    return rasterise_strokes(strokes, texels, texels);
  };
  // Twigs and leaves closer together or further apart (bisection on the scale of both gaps, judged
  // on an eighth-size drawing of the same strokes) until the spray covers leaf.coverage of the card.
  double lo = 0.25, hi = 4.0, best_scale = 1.0, best_error = 2.0;
  for (int step = 0; step < kCoverageSteps; ++step) {
    const double scale = std::sqrt(lo * hi);
    const double c = coverage(*draw(scale, std::max(size / 8, 64)));
    if (std::abs(c - leaf.coverage) < best_error) {
      best_error = std::abs(c - leaf.coverage);
      best_scale = scale;
    }
    (c > leaf.coverage ? lo : hi) = scale;
  }
  auto mask = draw(best_scale, size);
  mask->feature_length = L;
  return mask;
}

std::shared_ptr<const AlphaMask> spruce_spray(float card_side_m) { return family<kSpruce, 1>(card_side_m); }
std::shared_ptr<const AlphaMask> pine_spray(float card_side_m) { return family<kPine, 2>(card_side_m); }
std::shared_ptr<const AlphaMask> larch_spray(float card_side_m) { return family<kLarch, 3>(card_side_m); }
std::shared_ptr<const AlphaMask> beech_spray(float card_side_m) { return family<kBeech, 4>(card_side_m); }
std::shared_ptr<const AlphaMask> birch_spray(float card_side_m) { return family<kBirch, 5>(card_side_m); }
std::shared_ptr<const AlphaMask> oak_spray(float card_side_m) { return family<kOak, 6>(card_side_m); }
std::shared_ptr<const AlphaMask> bare_twig_spray(float card_side_m) { return family<kTwigs, 7>(card_side_m); }

std::span<const SprayFamily> spray_families() {
  static constexpr SprayFamily kFamilies[] = {spruce_spray, pine_spray,  larch_spray,    beech_spray,
                                              birch_spray,  oak_spray,   bare_twig_spray};
  return kFamilies;
}

std::shared_ptr<const AlphaMask> bare_twigs_for(const AlphaMask* leafy) {
  for (const MaskFamily leafy_family : {&beech_spray, &birch_spray, &oak_spray, &larch_spray})
    for (int k = 0; k < kSprayClasses; ++k) {
      const float side = kSprayClassSide * float(1 << k);
      if (leafy_family(side).get() == leafy) return bare_twig_spray(side);
    }
  return nullptr;
}

}  // namespace silva::assets
