#pragma once

#include <vector>

namespace strahler::quality {

/// Wavelengths (metres) over which spectralSlope fits: from 4 cells up to this.
inline constexpr double kSpectralLongestWavelengthM = 2000.0;

/// blind_set.py's spectral_slope(): minus the slope of the radially averaged power spectrum of a
/// width × height window of heights (row-major, cell side `cellSize` metres), in log–log.
/// The heights less their mean are multiplied by a 2-D Hann window (numpy.hanning per axis),
/// transformed by the exact-size 2-D DFT and squared (P = |F|²); each frequency has the radial
/// wavenumber K = hypot(fx, fy) (numpy.fft.fftfreq, cycles per metre). Frequencies with
/// 1/2000 < K < 1/(4·cell) give points (log10 K, log10(P + 1e-30)); the log10 K range is cut
/// into 15 equal bins (upper edge exclusive); each bin with more than 3 points gives (its
/// centre, the mean of its log10 P); the result is −(least-squares slope) over those bins.
/// Larger means less short-wavelength detail. NaN with 3 bins or fewer.
double spectralSlope(const std::vector<double>& heights, int width, int height, double cellSize);

} // namespace strahler::quality
