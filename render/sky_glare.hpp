#pragma once
/// @file Veiling glare of the sky (CONTRACT.md "Camera model", `camera.bloom`): a lens and sensor spread a
/// small share of the light of every pixel over a wide halo, so the bright sky seen through a canopy glows
/// into the leaf edges and trunks around it. Only the sky is spread (the forest's own glare is a faint even
/// veil): the sky's light per 4x4 block of the frame, blurred at three widths, added to every pixel, the
/// sky pixels giving up the share they spread.
#include <vector>

#include "core/camera.hpp"
#include "render/gbuffer.hpp"
#include "render/linear_frame.hpp"
#include "render/sky.hpp"

namespace silva::render {

/// Pixels per side of a block of the glare's source map.
inline constexpr int kGlareBlock = 4;
/// The halo: the blurs of the source map over 1, 4 and 16 blocks (about 4, 16 and 64 pixels) and their weights.
inline constexpr int kGlareLevels = 3;
inline constexpr int kGlareLevelBlocks[kGlareLevels] = {1, 4, 16};
inline constexpr float kGlareLevelWeights[kGlareLevels] = {0.5f, 0.3f, 0.2f};
/// A source block's radiance is at most this many times the sky's mean radiance: the sun's disc glares as a
/// very bright patch of sky (a lens flare is not modelled).
inline constexpr float kGlareSourceCap = 12.0f;

/// The sky glare of one frame.
class SkyGlare {
 public:
  /// The glare of the sky pixels (depth 0) of `g` seen by `camera` under `sky`, spreading the share
  /// `strength` of their light (0: none).
  SkyGlare(const GBuffer& g, const Camera& camera, const Sky& sky, float strength);

  /// True when the frame has glare to add.
  bool active() const { return active_; }

  /// Adds the halo to row v's linear radiance (the G-buffer's width of values) and takes the spread share
  /// from its sky pixels: L' = L + k (halo - L) on sky pixels, L + k halo elsewhere.
  void apply_row(int v, Vec3f* radiance) const;

 private:
  const GBuffer& g_;
  float strength_;
  bool active_ = false;
  LinearFrame halo_;  ///< The blurred sky light per block (pixel units of the block grid).
  /// The two halo columns a pixel column lies between and the right one's weight.
  struct Column {
    int left, right;
    float weight;
  };
  std::vector<Column> columns_;  ///< Per pixel column.
};

}  // namespace silva::render
