#include "core/rng.hpp"

#include <cmath>

namespace silva {

RngStreamBits::RngStreamBits(uint64_t world_seed, uint64_t key, uint64_t purpose) {
  uint64_t h = mix64(world_seed + 0x9e3779b97f4a7c15ULL);
  h = mix64(h ^ (key + 0x632be59bd9b4e019ULL));
  prefix_ = mix64(h ^ (purpose * 0x85ebca6bULL + 0xc2b2ae3d27d4eb4fULL));
}

uint64_t rng_bits(uint64_t world_seed, uint64_t key, uint64_t purpose, uint64_t index) {
  return RngStreamBits(world_seed, key, purpose)(index);
}

uint64_t hash_combine(uint64_t a, uint64_t b) { return mix64(mix64(a) ^ (b + 0x9e3779b97f4a7c15ULL)); }

float Rng::normal() {
  // Box-Muller; u1 in (0, 1] so log is finite.
  const double u1 = 1.0 - uniform_double();
  const double u2 = uniform_double();
  return float(std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2));
}

size_t Rng::choice(std::span<const float> weights) {
  double total = 0;
  for (float w : weights) total += w;
  double target = uniform_double() * total;
  for (size_t i = 0; i < weights.size(); ++i) {
    if (target < weights[i]) return i;
    target -= weights[i];
  }
  // Rounding can leave target just past the end: return the last positive weight.
  for (size_t i = weights.size(); i-- > 0;)
    if (weights[i] > 0) return i;
  return 0;
}

}  // namespace silva
