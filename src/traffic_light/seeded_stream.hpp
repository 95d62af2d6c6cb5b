// Portable seeded random streams shared by the fault models (perception_model, v2i_channel):
// splitmix64 to spread (seed, stream) into a seed, and uniforms made from raw mt19937_64 draws, so a
// sequence is identical on every platform and library version.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace signalsim::seeded {

/// splitmix64 (Steele, Lea, Flood 2014).
inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

/// The streams of the fault models. A light's camera and V2I channel share one seed (step/light_stage),
/// so every stream has its own index here.
inline constexpr std::uint64_t kCameraDropoutStream = 1;
inline constexpr std::uint64_t kMisclassificationStream = 2;
inline constexpr std::uint64_t kConfidenceStream = 3;
inline constexpr std::uint64_t kV2iDropoutStream = 4;
inline constexpr std::uint64_t kOmissionStream = 5;

/// The seed of stream `stream` of a model seeded with `seed`.
inline std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t stream) { return splitmix64(splitmix64(seed) ^ stream); }

/// Uniform in [0, 1) from the top 53 bits of one raw draw: exact and portable.
inline double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace signalsim::seeded
