#pragma once
/// @file Counter-based deterministic randomness: the only source of randomness in Silva.
/// Every draw is a pure function of (world_seed, key, purpose, index); there is no state
/// shared between draws, so results never depend on thread timing or call order.
#include <cstdint>
#include <cstddef>
#include <span>

namespace silva {

/// Purposes name what a random stream is used for, so two uses never share values.
enum class Purpose : uint32_t {
  TerrainOffset = 1,
  TrailWalk = 2,
  PlacementClass = 10,
  PlacementPosition = 11,
  PlacementScale = 12,
  PlacementYaw = 13,
  PlacementVariant = 14,
  GroundCover = 15,
  ResolveMove = 16,
  ResolvePriority = 17,
  ForestType = 18,
  TrailSurface = 19,
  AssetShape = 20,
  RandomPose = 30,
  SensorNoise = 40,
  MaterialNoise = 41,
  WeatherOverlay = 42,
  LidarNoise = 43,
  LightingRandomize = 44,
  ImuNoise = 45,
  VerifySample = 50,
  Test = 1000,
};

/// SplitMix64 finaliser: a bijective avalanche mix of one word.
inline uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// rng_bits of one (world_seed, key, purpose) for any index: the words that do not depend on the
/// index are mixed once, so each draw costs one mix.
class RngStreamBits {
 public:
  /// Mixes the stream's three fixed words.
  RngStreamBits(uint64_t world_seed, uint64_t key, uint64_t purpose);
  /// rng_bits(world_seed, key, purpose, index).
  uint64_t operator()(uint64_t index) const { return mix64(prefix_ ^ (index + 0x165667b19e3779f9ULL)); }

 private:
  uint64_t prefix_;  ///< The three fixed words, mixed.
};

/// Mixes four 64-bit words into a well-distributed 64-bit hash (stateless).
uint64_t rng_bits(uint64_t world_seed, uint64_t key, uint64_t purpose, uint64_t index);

/// A random stream for one (seed, key, purpose): draw i is rng_bits(seed, key, purpose, i).
/// Successive helper calls advance an internal counter; copying a stream copies the counter.
class Rng {
 public:
  /// Opens the stream (world_seed, key, purpose) starting at draw `start_index`.
  Rng(uint64_t world_seed, uint64_t key, Purpose purpose, uint64_t start_index = 0)
      : seed_(world_seed), key_(key), purpose_(uint64_t(purpose)), index_(start_index) {}

  /// Next raw 64-bit value.
  uint64_t next_u64() { return rng_bits(seed_, key_, purpose_, index_++); }
  /// Uniform float in [0, 1) with 24 bits of precision.
  float uniform() { return float(next_u64() >> 40) * (1.0f / 16777216.0f); }
  /// Uniform double in [0, 1) with 53 bits of precision.
  double uniform_double() { return double(next_u64() >> 11) * (1.0 / 9007199254740992.0); }
  /// Uniform float in [lo, hi).
  float range(float lo, float hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n); n must be > 0.
  uint32_t below(uint32_t n) { return uint32_t((next_u64() >> 32) * uint64_t(n) >> 32); }
  /// Standard normal draw (Box-Muller on two uniforms).
  float normal();
  /// Normal draw with the given mean and standard deviation.
  float normal(float mean, float stddev) { return mean + stddev * normal(); }
  /// Index chosen with probability proportional to weights[i]; weights must not all be 0.
  size_t choice(std::span<const float> weights);

 private:
  uint64_t seed_, key_, purpose_, index_;
};

/// Combines two 64-bit values into one key (order-sensitive).
uint64_t hash_combine(uint64_t a, uint64_t b);

}  // namespace silva
