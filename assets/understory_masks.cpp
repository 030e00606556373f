#include "assets/understory_masks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/mask_strokes.hpp"

namespace silva::assets {

namespace {

using Shape = Stroke::Shape;

/// A blade from `base` bending by `bend` degrees over its length, as three tapering segments.
void add_blade(std::vector<Stroke>& s, Vec2f base, float deg, float bend, float len, float half) {
  for (int k = 0; k < 3; ++k) {
    const Vec2f next = stroke_towards(base, deg + bend * float(k) / 2.0f, len / 3.0f);
    s.push_back({base, next, half * (1.0f - float(k) / 3.0f), half * (1.0f - float(k + 1) / 3.0f)});
    base = next;
  }
}

/// Deterministic pseudo-random value in [0, 1) for mask layouts (same every run).
float jitter(int i, int salt) {
  uint32_t h = uint32_t(i) * 0x9e3779b1u ^ uint32_t(salt) * 0x85ebca6bu;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  return float(h >> 8) * (1.0f / 16777216.0f);
}

/// A tuft of `count` blades across the mask bottom (mask units, height `h`).
void add_tuft(std::vector<Stroke>& s, int count, float h, float min_len, int salt) {
  for (int i = 0; i < count; ++i) {
    const float x = 0.1f + 0.8f * (float(i) + jitter(i, salt)) / float(count);
    const float lean = (x - 0.5f) * 50.0f + 20.0f * (jitter(i, salt + 1) - 0.5f);
    const float len = h * (min_len + (1.0f - min_len) * jitter(i, salt + 2));
    add_blade(s, {x, h}, lean, lean > 0 ? 18.0f : -18.0f, len, 0.022f + 0.01f * jitter(i, salt + 3));
  }
}

/// A nettle leaf of length `len` from `base` at angle `deg`: broad ovate below, drawn out to a long point,
/// with eight forward-pointing teeth a side along the whole edge.
void add_nettle_leaf(std::vector<Stroke>& s, const Vec2f& base, float deg, float len) {
  constexpr float kPi = std::numbers::pi_v<float>;
  constexpr float kBroad = 0.6f, kTipFrom = 0.2f;  // the broad part's reach, the tip's start (shares of len)
  const float broad = 0.3f * len, tip = 0.22f * len;
  s.push_back({base, stroke_towards(base, deg, kBroad * len), broad, 0, Shape::Round});
  s.push_back({stroke_towards(base, deg, kTipFrom * len), stroke_towards(base, deg, len), tip, 0, Shape::Pointed});
  constexpr int kTeeth = 8;
  for (int k = 0; k < kTeeth; ++k) {
    const float t = 0.12f + 0.76f * (float(k) + 0.5f) / float(kTeeth);
    const float w = std::max(t < kBroad ? broad * std::pow(std::sin(kPi * t / kBroad), 0.35f) : 0.0f,
                             t > kTipFrom ? tip * std::pow(std::sin(kPi * (t - kTipFrom) / (1.0f - kTipFrom)), 0.7f) : 0.0f);
    const Vec2f on = stroke_towards(base, deg, t * len);
    for (float side : {-1.0f, 1.0f}) {
      const Vec2f edge = stroke_towards(on, deg + side * 90.0f, 0.75f * w);
      s.push_back({edge, stroke_towards(edge, deg + side * 50.0f, 0.35f * w + 0.02f * len), 0.045f * len, 0,
                   Shape::Pointed});
    }
  }
}

}  // namespace

std::shared_ptr<const AlphaMask> pinnate_frond_mask() {
  static const auto mask = [] {
    const float h = float(kFrondMaskHeight) / float(kFrondMaskWidth);
    std::vector<Stroke> s = {{{0.5f, h}, {0.5f, 0.02f}, 0.022f, 0.008f}};
    constexpr int kPairs = 18;
    for (int i = 0; i < kPairs; ++i) {
      const float f = (float(i) + 0.5f) / float(kPairs);  // 0 at the lowest pinna, 1 at the tip
      const Vec2f on(0.5f, h * (0.86f - 0.84f * f));
      const float len = 0.47f * std::pow(std::sin(std::numbers::pi_v<float> * (0.12f + 0.88f * f)), 0.8f);
      const float half = 0.05f + 0.03f * len;
      for (float side : {-1.0f, 1.0f}) {
        const float deg = side * (65.0f - 15.0f * f);
        const Vec2f tip = stroke_towards(on, deg, len);
        s.push_back({on, tip, half, 0, Shape::Pointed});
        for (int k = 1; k <= 4; ++k) {  // pinnules: lobes along both edges of the pinna
          const Vec2f p = on + (0.2f * float(k)) * (tip - on);
          for (float edge : {-1.0f, 1.0f})
            s.push_back({p, stroke_towards(p, deg + edge * 50.0f, 0.9f * half), 0.45f * half, 0, Shape::Pointed});
        }
      }
    }
    return rasterise_strokes(s, kFrondMaskWidth, kFrondMaskHeight);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> grass_tuft_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s;
    add_tuft(s, 16, 2.0f, 0.35f, 1);
    return rasterise_strokes(s, 64, 128);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> grass_seed_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s;
    add_tuft(s, 10, 2.0f, 0.25f, 7);
    for (int i = 0; i < 3; ++i) {  // flowering stalks ending in a spike-like seed head
      const Vec2f base(0.3f + 0.2f * float(i), 2.0f);
      const float lean = -12.0f + 12.0f * float(i);
      const Vec2f top = stroke_towards(base, lean, 1.45f + 0.15f * jitter(i, 9));
      s.push_back({base, top, 0.012f, 0.009f});
      s.push_back({top, stroke_towards(top, lean + 6.0f, 0.42f), 0.045f, 0, Shape::Pointed});
      for (int k = 0; k < 4; ++k) {  // loose spikelets along the head
        const Vec2f p = stroke_towards(top, lean, 0.08f + 0.08f * float(k));
        const float side = k % 2 ? 1.0f : -1.0f;
        s.push_back({p, stroke_towards(p, lean + side * 35.0f, 0.09f), 0.022f, 0, Shape::Pointed});
      }
    }
    return rasterise_strokes(s, 64, 128);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> grass_sward_mask() {
  static const auto mask = [] {
    const float h = float(kGrassSwardMaskHeight) / float(kGrassSwardMaskWidth);
    std::vector<Stroke> s;
    for (int i = 0; i < kGrassSwardBlades; ++i) {  // upright fine blades side by side, each its own shade
      const float x = 0.06f + 0.88f * (float(i) + jitter(i, 31)) / float(kGrassSwardBlades);
      const float lean = 30.0f * (jitter(i, 32) - 0.5f) - 16.0f * (x - 0.5f);  // edge blades lean inwards
      const size_t first = s.size();
      add_blade(s, {x, h}, lean, lean > 0 ? 14.0f : -14.0f, h * (0.45f + 0.55f * jitter(i, 33)),
                kGrassSwardBladeHalfWidth[0] + (kGrassSwardBladeHalfWidth[1] - kGrassSwardBladeHalfWidth[0]) * jitter(i, 34));
      for (size_t k = first; k < s.size(); ++k) s[k].alpha = uint8_t(150 + int(100.0f * jitter(i, 35)));
    }
    return rasterise_strokes(s, kGrassSwardMaskWidth, kGrassSwardMaskHeight);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> bilberry_leaves_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s;
    const float twig_deg[] = {-35.0f, 0.0f, 30.0f, 60.0f};
    for (int t = 0; t < 4; ++t) {
      const Vec2f base(0.25f + 0.15f * float(t), 1.0f);
      const Vec2f top = stroke_towards(base, twig_deg[t] - 15.0f, 0.85f);
      s.push_back({base, top, 0.012f, 0.008f});
      for (int k = 0; k < 6; ++k) {  // alternate small oval leaves
        const Vec2f on = base + (0.22f + 0.13f * float(k)) * (top - base);
        const float side = k % 2 ? 1.0f : -1.0f;
        add_leaf_strokes(s, on, twig_deg[t] - 15.0f + side * 55.0f, 0.13f, 0.045f, 0);
      }
    }
    return rasterise_strokes(s, 64, 64);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> hazel_leaves_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s;
    const Vec2f c(0.5f, 0.55f);
    const float deg[] = {-70.0f, 5.0f, 75.0f};
    const float len[] = {0.38f, 0.45f, 0.36f};
    for (int i = 0; i < 3; ++i) {
      const Vec2f base = stroke_towards(c, deg[i], 0.05f);
      s.push_back({c, base, 0.012f, 0.01f});
      add_leaf_strokes(s, base, deg[i], len[i], 0.42f * len[i], 5);
    }
    return rasterise_strokes(s, 64, 64);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> bramble_leaf_mask() {
  static const auto mask = [] {
    const Vec2f base(0.5f, 1.0f), hub(0.5f, 0.62f);
    std::vector<Stroke> s = {{base, hub, 0.014f, 0.012f}};
    const float deg[] = {-100.0f, -50.0f, 0.0f, 50.0f, 100.0f};
    const float len[] = {0.2f, 0.3f, 0.4f, 0.3f, 0.2f};
    for (int i = 0; i < 5; ++i) add_leaf_strokes(s, stroke_towards(hub, deg[i], 0.03f), deg[i], len[i], 0.38f * len[i], 4);
    return rasterise_strokes(s, 64, 64);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> wood_sorrel_leaf_mask() {
  static const auto mask = [] {
    const Vec2f hub(0.5f, 0.5f);
    std::vector<Stroke> s;
    for (int i = 0; i < 3; ++i) {  // each leaflet a pair of round lobes: broad, notched at the tip
      const float deg = 120.0f * float(i) + 8.0f;
      const auto shade = uint8_t(160 + 40 * i);  // leaflets of one leaf differ a little in brightness
      for (float lobe : {-19.0f, 19.0f})
        s.push_back({hub, stroke_towards(hub, deg + lobe, 0.43f), 0.12f, 0, Shape::Round, shade});
    }
    return rasterise_strokes(s, kWoodSorrelMaskSize, kWoodSorrelMaskSize);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> woodruff_whorl_mask() {
  static const auto mask = [] {
    const Vec2f hub(0.5f, 0.5f);
    std::vector<Stroke> s;
    for (int i = 0; i < kWoodruffWhorlLeaves; ++i) {  // evenly round the stem, a little uneven in angle and length
      const float deg = (360.0f / float(kWoodruffWhorlLeaves)) * (float(i) + 0.25f * (jitter(i, 41) - 0.5f));
      const float len = 0.4f + 0.06f * jitter(i, 42);
      const auto shade = uint8_t(130 + int(70.0f * jitter(i, 43)));  // darker than wood sorrel, as the plant is
      s.push_back({stroke_towards(hub, deg, 0.02f), stroke_towards(hub, deg, len), 0.045f, 0, Shape::Pointed, shade});
    }
    return rasterise_strokes(s, kWoodruffMaskSize, kWoodruffMaskSize);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> nettle_pair_mask() {
  static const auto mask = [] {
    const Vec2f hub(0.5f, 0.5f);
    std::vector<Stroke> s;
    for (int i = 0; i < 2; ++i) {  // opposite, a little off the straight line and unequal
      const float deg = 90.0f + 180.0f * float(i) + 10.0f * (jitter(i, 51) - 0.5f);
      const size_t first = s.size();
      const Vec2f base = stroke_towards(hub, deg, 0.03f);
      s.push_back({hub, base, 0.01f, 0.008f});  // the leaf stalk
      add_nettle_leaf(s, base, deg, 0.4f + 0.03f * jitter(i, 52));
      const auto shade = uint8_t(128 + int(47.0f * jitter(i, 53)));
      for (size_t k = first; k < s.size(); ++k) s[k].alpha = shade;
    }
    return rasterise_strokes(s, kNettleMaskSize, kNettleMaskSize);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> wood_anemone_whorl_mask() {
  static const auto mask = [] {
    const Vec2f hub(0.5f, 0.5f);
    std::vector<Stroke> s;
    for (int i = 0; i < 3; ++i) {
      const float deg = 120.0f * float(i) + 20.0f * (jitter(i, 61) - 0.5f);
      const size_t first = s.size();
      const Vec2f fork = stroke_towards(hub, deg, 0.12f);  // the leaf stalk, then three narrow segments fanning out
      s.push_back({hub, fork, 0.012f, 0.01f});
      for (int k = -1; k <= 1; ++k) {
        const float seg = deg + 46.0f * float(k), len = (k == 0 ? 0.34f : 0.28f) + 0.02f * jitter(3 * i + k + 1, 62);
        add_leaf_strokes(s, fork, seg, len, 0.17f * len, 3);
      }
      const auto shade = uint8_t(140 + int(60.0f * jitter(i, 63)));
      for (size_t k = first; k < s.size(); ++k) s[k].alpha = shade;
    }
    return rasterise_strokes(s, kWoodAnemoneMaskSize, kWoodAnemoneMaskSize);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> wood_anemone_flower_mask() {
  static const auto mask = [] {
    const Vec2f hub(0.5f, 0.5f);
    // The stamens: a darker (yellow) disc in the middle.
    std::vector<Stroke> s = {{hub - Vec2f(0.001f, 0), hub + Vec2f(0.001f, 0), 0.09f, 0.09f, Shape::Tapered, 150}};
    for (int i = 0; i < kWoodAnemoneTepals; ++i) {
      const float deg = (360.0f / float(kWoodAnemoneTepals)) * (float(i) + 0.2f * (jitter(i, 71) - 0.5f));
      const auto shade = uint8_t(215 + int(40.0f * jitter(i, 72)));
      s.push_back({stroke_towards(hub, deg, 0.06f), stroke_towards(hub, deg, 0.45f), 0.12f, 0, Shape::Round, shade});
    }
    return rasterise_strokes(s, kWoodAnemoneMaskSize, kWoodAnemoneMaskSize);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> herb_stalk_mask() {
  static const auto mask = [] {
    const float h = float(kHerbStalkMaskHeight) / float(kHerbStalkMaskWidth);
    return rasterise_strokes({{{0.5f, h}, {0.5f, 0.0f}, 0.17f, 0.12f}}, kHerbStalkMaskWidth, kHerbStalkMaskHeight);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> litter_leaves_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s;
    for (int i = 0; i < 6; ++i) {
      const Vec2f base(0.2f + 0.6f * jitter(i, 21), 0.25f + 0.6f * jitter(i, 22));
      const float len = 0.2f + 0.12f * jitter(i, 23);
      add_leaf_strokes(s, base, 360.0f * jitter(i, 24), len, (i % 3 ? 0.3f : 0.4f) * len, i % 3 ? 0 : 3);
    }
    return rasterise_strokes(s, 64, 64);
  }();
  return mask;
}

}  // namespace silva::assets
