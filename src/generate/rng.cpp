// Rng::index by rejection (see rng.hpp for the documented algorithm).
#include "generate/rng.hpp"

#include <limits>

namespace signalsim::generate {

std::size_t Rng::index(std::size_t n) {
  if (n <= 1) return 0;
  const std::uint64_t range = static_cast<std::uint64_t>(n);
  // 2^64 mod n, computed without 128-bit arithmetic: (2^64 - n) mod n == 2^64 mod n.
  const std::uint64_t rest = (std::numeric_limits<std::uint64_t>::max() - range + 1) % range;
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - rest;  // 2^64 - rest - 1
  while (true) {
    const std::uint64_t x = next();
    // Accept x in [0, 2^64 - rest): that many values are a whole number of copies of [0, n).
    if (rest == 0 || x <= limit) return static_cast<std::size_t>(x % range);
  }
}

long long Rng::between(long long lo, long long hi) {
  if (hi <= lo) return lo;
  return lo + static_cast<long long>(index(static_cast<std::size_t>(hi - lo) + 1));
}

}  // namespace signalsim::generate
