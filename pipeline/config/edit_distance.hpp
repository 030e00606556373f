#pragma once
/// @file Levenshtein edit distance, used to suggest the closest valid name for a typo.
#include <cstddef>
#include <string_view>

namespace silva::pipeline {

/// Number of single-character insertions, deletions and substitutions turning `a` into `b`.
size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace silva::pipeline
