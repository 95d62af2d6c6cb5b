// The generator's random numbers: one fixed, documented algorithm, so that `signalsim generate`
// writes the same files for the same seed on every machine and standard library.
//
// The engine is std::mt19937_64 (its output sequence is fixed by the C++ standard, [rand.eng.mers]),
// seeded with the 64-bit seed itself. The standard's distributions (std::uniform_int_distribution,
// ...) are implementation-defined, so none is used: an index in [0, n) is drawn by rejection,
//   limit := 2^64 - (2^64 mod n);  draw x until x < limit;  return x mod n
// (unbiased; at most a few draws). Nothing else consumes engine output.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

namespace signalsim::generate {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  /// The engine's next raw 64-bit output.
  std::uint64_t next() { return engine_(); }

  /// Uniform in [0, n); n >= 1 (n == 0 returns 0 without drawing).
  std::size_t index(std::size_t n);

  /// Uniform integer in [lo, hi] (lo <= hi).
  long long between(long long lo, long long hi);

 private:
  std::mt19937_64 engine_;
};

}  // namespace signalsim::generate
