#pragma once
/// @file Skeletons of dead trees: a grown trunk with broken-off branches and, when snapped, a
/// broken top; shared by standing snags and fallen trees.
#include "assets/tree_skeleton.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// Cuts branch `i` at fraction t of its length and removes every branch that forked off beyond
/// t (and their descendants); parent links of the rest are renumbered.
void truncate_branch(Skeleton& s, size_t i, float t);

/// A dead tree of trunk length `length` and base radius `r0` (three orders, the finest meant for
/// twig cards); first-order branches droop low on the trunk and rise higher up, crooked, 70 % of them
/// broken off at 10-60 % of their length; the trunk snapped at `top` (0-1]
/// of its length (1 = intact top).
Skeleton dead_skeleton(float length, float r0, float top, Rng& rng);

}  // namespace silva::assets
