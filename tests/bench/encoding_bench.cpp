// Heightmap tile encoding: every format at 256² and 512² on three kinds of terrain, and the
// PNG settings the encoder chose from (zlib level × row filter × zlib strategy) on 256²
// Terrain-RGB tiles. kind: 0 rough hills (30 m pixels, ±0.5 m noise), 1 smooth hills (2 m
// pixels), 2 sea shelf.
//
//   cmake --preset release && cmake --build build/release --target strahler_encoding_bench
//   taskset -c 0 build/release/tests/bench/strahler_encoding_bench
//
// Counter "bytes" is the encoded size of one tile. OpenEXR compresses on its own thread pool:
// for exr read the Time column (wall clock), not CPU (the calling thread only).

#include "png_encoder.h"

#include "strahler/encoding/heightmap_encoder.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using strahler::encoding::HeightGrid;
using strahler::encoding::HeightmapFormat;
namespace detail = strahler::encoding::detail;

/// Uniform in [−1, 1) from an integer hash of the pixel: deterministic sub-metre roughness.
double hashNoise(int x, int y) {
  auto h =
      static_cast<std::uint32_t>(x) * 0x8da6b343u ^ static_cast<std::uint32_t>(y) * 0xd8163841u;
  h ^= h >> 13;
  h *= 0x85ebca6bu;
  h ^= h >> 16;
  return static_cast<double>(h) / 2147483648.0 - 1.0;
}

/// Tiles the encoder meets: rough hills at a coarse zoom, the same hills zoomed in (smooth
/// from pixel to pixel), and a sea shelf (almost flat).
enum TerrainKind { kRough, kSmooth, kShelf };

/// Octaves of sines, metres in and out: wavelengths from 48 km down to 560 m, amplitudes
/// 900 m … 5 m.
double hills(double x, double y) {
  double h = 1200.0;
  double amplitude = 900.0;
  double frequency = 0.00013;
  for (int octave = 0; octave < 7; ++octave) {
    h += amplitude * std::sin(frequency * x + octave * 1.7) *
         std::cos(frequency * 0.83 * y + octave);
    amplitude *= 0.42;
    frequency *= 2.1;
  }
  return h;
}

double heightAt(TerrainKind kind, int x, int y) {
  switch (kind) {
  case kRough: // 30 m pixels with ±0.5 m of pixel noise, as real DEM tiles have
    return hills(30.0 * x, 30.0 * y) + 0.5 * hashNoise(x, y);
  case kSmooth: // 2 m pixels
    return hills(2.0 * x, 2.0 * y);
  case kShelf: // −20 m to −80 m across the tile with a gentle swell
    return -20.0 - 0.25 * (x + y) / 2.0 + 1.5 * std::sin(0.02 * x) * std::cos(0.015 * y);
  }
  return 0.0;
}

HeightGrid terrain(int size, TerrainKind kind) {
  HeightGrid grid{size, size, {}};
  grid.heights.reserve(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      grid.heights.push_back(static_cast<float>(heightAt(kind, x, y)));
  return grid;
}

/// Args: tile side, TerrainKind.
/// Times `encode` (returning a Result of bytes) over the benchmark's iterations and reports the
/// encoded size, or skips with the encoder's error.
template <class Encode> void measureEncoding(benchmark::State& state, Encode&& encode) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto encoded = encode();
    if (!encoded.ok()) {
      state.SkipWithError(encoded.error().message.c_str());
      return;
    }
    bytes = encoded.value().size();
    benchmark::DoNotOptimize(encoded);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}

void encodeFormat(benchmark::State& state, HeightmapFormat format) {
  const HeightGrid grid =
      terrain(static_cast<int>(state.range(0)), static_cast<TerrainKind>(state.range(1)));
  measureEncoding(state, [&] { return strahler::encoding::encodeHeightmap(grid, format); });
}

void formatArgs(benchmark::internal::Benchmark* bench) {
  bench->ArgNames({"size", "kind"})->Unit(benchmark::kMicrosecond);
  for (const int size : {256, 512})
    for (const int kind : {kRough, kSmooth, kShelf})
      bench->Args({size, kind});
}

BENCHMARK_CAPTURE(encodeFormat, terrain_rgb, HeightmapFormat::kTerrainRgb)->Apply(formatArgs);
BENCHMARK_CAPTURE(encodeFormat, terrarium, HeightmapFormat::kTerrarium)->Apply(formatArgs);
BENCHMARK_CAPTURE(encodeFormat, png16, HeightmapFormat::kPng16)->Apply(formatArgs);
BENCHMARK_CAPTURE(encodeFormat, tiff, HeightmapFormat::kTiff)->Apply(formatArgs);
BENCHMARK_CAPTURE(encodeFormat, exr, HeightmapFormat::kExr)->Apply(formatArgs);

/// Terrain-RGB bytes of a 256² tile, packed as the encoder does.
std::vector<std::uint8_t> terrainRgbSamples(TerrainKind kind) {
  std::vector<std::uint8_t> samples;
  for (const float h : terrain(256, kind).heights) {
    const auto code =
        static_cast<std::uint32_t>(std::round((static_cast<double>(h) + 10000.0) * 10.0));
    samples.insert(samples.end(),
                   {static_cast<std::uint8_t>(code >> 16), static_cast<std::uint8_t>(code >> 8),
                    static_cast<std::uint8_t>(code)});
  }
  return samples;
}

/// Args: TerrainKind, zlib level, PngFilter, ZlibStrategy.
void pngSettings(benchmark::State& state) {
  static const std::vector<std::uint8_t> samples[] = {
      terrainRgbSamples(kRough), terrainRgbSamples(kSmooth), terrainRgbSamples(kShelf)};
  const detail::PngOptions options{static_cast<int>(state.range(1)),
                                   static_cast<detail::PngFilter>(state.range(2)),
                                   static_cast<detail::ZlibStrategy>(state.range(3))};
  const auto& tile = samples[state.range(0)];
  measureEncoding(
      state, [&] { return detail::encodePng(tile, 256, 256, detail::PngLayout::kRgb8, options); });
}

/// Per terrain kind: every level 1..6 with every filter under zlib's default strategy, then
/// every strategy with every filter at level 1 (the fast end, where strategies differ most).
void pngSettingsArgs(benchmark::internal::Benchmark* bench) {
  bench->ArgNames({"kind", "level", "filter", "strategy"})->Unit(benchmark::kMicrosecond);
  for (const int kind : {kRough, kSmooth, kShelf}) {
    for (int level = 1; level <= 6; ++level)
      for (int filter = 0; filter <= 5; ++filter)
        bench->Args({kind, level, filter, 0});
    for (int strategy = 1; strategy <= 3; ++strategy)
      for (int filter = 0; filter <= 5; ++filter)
        bench->Args({kind, 1, filter, strategy});
  }
}

BENCHMARK(pngSettings)->Apply(pngSettingsArgs);

} // namespace
