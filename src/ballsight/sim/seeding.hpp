#pragma once
// Seeded randomness for the simulators: independent streams derived from one user seed, and
// uniform draws computed from the raw 64-bit engine output so that a seed gives the same scene on
// every standard library (std::uniform_real_distribution is implementation-defined).

#include <cstdint>
#include <random>

namespace ballsight::sim {

/// A seed for sub-stream `stream` of `seed` (SplitMix64 finaliser of both).
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// Uniform in [lo, hi).
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  const double unit = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * unit;
}

/// Uniform integer in [lo, hi] (the tiny modulo bias is irrelevant for scene generation).
inline int uniform_int(std::mt19937_64& rng, int lo, int hi) {
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<int>(rng() % span);
}

}  // namespace ballsight::sim
