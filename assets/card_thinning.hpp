#pragma once
/// @file Level-of-detail for alpha-tested card parts: fewer cards, each grown about its centre so
/// the part's total card area (and so, on average, the pixels it covers) stays the same.
#include <cstdint>
#include <vector>

#include "core/mesh.hpp"

namespace silva::assets {

/// The triangles (indices into mesh.positions) of the cards of `part` that a level at `ratio`
/// keeps: a card is a set of triangles joined by shared vertices; of n cards, max(1, round(n x
/// ratio)) spread evenly over the part's order are kept, and the positions of each kept card's
/// vertices in `positions` (a copy of mesh.positions) are scaled about the card's centre by
/// sqrt(n / kept). A part whose cards share vertices with other parts is returned whole.
std::vector<uint32_t> thin_cards(const Mesh& mesh, const MeshPart& part, float ratio, std::vector<Vec3f>& positions);

/// `mesh` with every card (alpha-masked) part thinned by thin_cards to `ratio`; solid parts unchanged.
Mesh with_thinned_cards(const Mesh& mesh, float ratio);

}  // namespace silva::assets
