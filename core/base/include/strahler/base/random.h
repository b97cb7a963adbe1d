#pragma once

#include <cstdint>

namespace strahler::base {

/// Deterministic random numbers (xoshiro256** seeded by splitmix64).
/// Unlike std distributions, every draw is specified here, so the same seed gives the
/// same sequence with any compiler or standard library.
class Rng {
public:
  /// A generator for `seed`; `stream` selects an independent sequence for the same seed.
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) noexcept;

  /// 64 uniformly random bits.
  std::uint64_t nextU64() noexcept;
  /// Uniform in [0, 1) with 53 bits of precision.
  double uniform() noexcept;
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n); n must be positive.
  std::uint32_t below(std::uint32_t n) noexcept;
  /// True with probability p.
  bool chance(double p) noexcept { return uniform() < p; }

private:
  std::uint64_t s_[4];
};

/// Mixes a value into a 64-bit hash state (splitmix64 finaliser), for seeding per item.
std::uint64_t mixHash(std::uint64_t state, std::uint64_t value) noexcept;

} // namespace strahler::base
