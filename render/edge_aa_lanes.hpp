#pragma once
/// @file The edge-antialiasing decision of render/edge_aa.hpp for a whole row on Highway SIMD lanes
/// (runtime dispatch): which pixels are edges, which neighbour each blends towards, and how much.
#include <cstddef>
#include <cstdint>

namespace silva::render {

/// Contrast (luma units 0..255) below which a pixel is left alone: absolute floor and relative share.
inline constexpr float kEdgeMinContrast = 8.0f;
inline constexpr float kEdgeRelativeContrast = 0.125f;
/// Largest blend towards the neighbour across the edge.
inline constexpr float kEdgeMaxBlend = 0.375f;

/// The neighbour an edge pixel blends towards.
enum class EdgeNeighbour : int32_t { North = 1, South = 2, East = 3, West = 4 };

/// Edge pixels of one row, compacted: column, blend weight and neighbour of each.
struct EdgeRow {
  int32_t* column = nullptr;     ///< Columns of the edge pixels, ascending.
  float* blend = nullptr;        ///< Share of the neighbour's colour (0 .. 3/8).
  int32_t* neighbour = nullptr;  ///< EdgeNeighbour of each.
};

/// Lanes of the target edge_blends_lanes dispatches to: the lumas must be readable this many
/// columns past `end`, and the outputs must hold this many entries past the edge count.
size_t edge_lane_padding();

/// Finds the edge pixels among columns [begin, end) of a row whose lumas (luma() of each pixel)
/// are `up`, `mid` and `down` for the rows above, at and below it (readable from begin - 1), and
/// writes them to `out`; returns how many there are. Each value is the scalar filter's: the same
/// correctly rounded float operations in the same order, so every target gives the same bits.
size_t edge_blends_lanes(const float* up, const float* mid, const float* down, int begin, int end, const EdgeRow& out);

}  // namespace silva::render
