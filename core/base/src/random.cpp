#include "strahler/base/random.h"

namespace strahler::base {
namespace {

std::uint64_t splitmix64(std::uint64_t& x) noexcept {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::uint64_t rotl(std::uint64_t x, int k) noexcept {
  return (x << k) | (x >> (64 - k));
}

} // namespace

Rng::Rng(std::uint64_t seed, std::uint64_t stream) noexcept {
  std::uint64_t x = seed ^ (stream * 0xD1B54A32D192ED03ull);
  for (auto& s : s_)
    s = splitmix64(x);
}

std::uint64_t Rng::nextU64() noexcept {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform() noexcept {
  return static_cast<double>(nextU64() >> 11) * 0x1.0p-53;
}

std::uint32_t Rng::below(std::uint32_t n) noexcept {
  // Lemire's multiply-shift; the tiny bias is irrelevant here and the result is exact.
  return static_cast<std::uint32_t>(((nextU64() >> 32) * static_cast<std::uint64_t>(n)) >> 32);
}

std::uint64_t mixHash(std::uint64_t state, std::uint64_t value) noexcept {
  std::uint64_t x = state ^ (value + 0x9E3779B97F4A7C15ull + (state << 6) + (state >> 2));
  return splitmix64(x);
}

} // namespace strahler::base
