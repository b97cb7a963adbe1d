#pragma once

// Which vector instruction sets this build has code for, and which one runs.

/// 1 where the build compiles x86 intrinsics (x86-64 with GCC or Clang, STRAHLER_SIMD=auto);
/// 0 for the portable path only (STRAHLER_SIMD=none, or any other target).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(STRAHLER_SIMD_NONE)
#define STRAHLER_SIMD_X86 1
#else
#define STRAHLER_SIMD_X86 0
#endif

namespace strahler::simd {

/// Vector instruction sets the kernels can run on; every one gives the same bits.
enum class InstructionSet {
  kBaseline, ///< SSE2 on x86-64; the portable code elsewhere or with STRAHLER_SIMD=none.
  kAvx2,     ///< 256-bit vectors.
  kAvx512,   ///< 512-bit vectors (AVX-512F and DQ).
};

/// Whether this build has code for `set` and this CPU can run it (kBaseline always).
bool supports(InstructionSet set) noexcept;
/// The set kernels use: the widest supported, unless useInstructionSet() chose another.
InstructionSet instructionSet() noexcept;
/// Runs kernels with `set` from now on, process-wide, if supported (for tests and benchmarks);
/// returns whether it is.
bool useInstructionSet(InstructionSet set) noexcept;

} // namespace strahler::simd
