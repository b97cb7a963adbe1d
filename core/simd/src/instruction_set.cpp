#include "strahler/simd/instruction_set.h"

#include <atomic>

namespace strahler::simd {
namespace {

InstructionSet widest() noexcept {
  for (InstructionSet set : {InstructionSet::kAvx512, InstructionSet::kAvx2})
    if (supports(set))
      return set;
  return InstructionSet::kBaseline;
}

std::atomic<InstructionSet>& current() noexcept {
  static std::atomic<InstructionSet> set{widest()};
  return set;
}

} // namespace

bool supports(InstructionSet set) noexcept {
  switch (set) {
  case InstructionSet::kAvx512:
#if STRAHLER_SIMD_X86
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
#else
    return false;
#endif
  case InstructionSet::kAvx2:
#if STRAHLER_SIMD_X86
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
  case InstructionSet::kBaseline:
    return true;
  }
  return false;
}

InstructionSet instructionSet() noexcept {
  return current().load(std::memory_order_relaxed);
}

bool useInstructionSet(InstructionSet set) noexcept {
  if (!supports(set))
    return false;
  current().store(set, std::memory_order_relaxed);
  return true;
}

} // namespace strahler::simd
