#pragma once

#include <complex>
#include <vector>

namespace strahler::quality {

/// In-place forward discrete Fourier transform of any length n ≥ 1:
/// X[k] = Σ_j x[j]·exp(−2πi·jk/n), unnormalised (numpy.fft.fft's convention). Radix-2
/// Cooley–Tukey for powers of two, Bluestein's chirp-z (through a power-of-two transform)
/// for every other length, so the result is the exact-size DFT, not a zero-padded one.
/// O(n log n); relative error ~1e-15·log n in double precision.
void fft(std::vector<std::complex<double>>& values);

/// In-place forward 2-D DFT of a row-major width × height array (numpy.fft.fft2's convention:
/// a 1-D fft along every row, then along every column).
void fft2(std::vector<std::complex<double>>& values, int width, int height);

} // namespace strahler::quality
