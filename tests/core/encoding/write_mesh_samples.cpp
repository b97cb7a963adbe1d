// Writes mesh tiles for the independent decoders in tests/node: for each sample <name>.drc,
// <name>.glb and <name>.json (the mesh we encoded, for check_draco.mjs to compare against).
// Usage: write_mesh_samples <output folder>

#include "synthetic_terrain.h"

#include "strahler/encoding/mesh.h"
#include "strahler/encoding/mesh_encoder.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace strahler::encoding;

struct Sample {
  std::string name;
  int quads;
  double spacing;
  strahler::geometry::Vec2 origin;
  bool textureCoordinates;
  DracoOptions options;
};

/// Shortest decimal that reads back as exactly this double (floats widen exactly).
std::string number(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

template <class T> void writeArray(std::ostream& out, const std::vector<T>& values) {
  out << '[';
  for (std::size_t k = 0; k < values.size(); ++k)
    out << (k ? "," : "") << number(static_cast<double>(values[k]));
  out << ']';
}

void writeExpected(const std::filesystem::path& path, const Sample& sample, const Mesh& mesh) {
  std::ofstream out(path);
  out << "{\"name\":\"" << sample.name << "\",\"drc\":\"" << sample.name << ".drc\""
      << ",\"glb\":\"" << sample.name << ".glb\""
      << ",\"maxPositionError\":" << number(sample.options.maxPositionError)
      << ",\"spacing\":" << number(sample.spacing)
      << ",\"hasUv\":" << (mesh.uvs.empty() ? "false" : "true") << ",\"origin\":["
      << number(mesh.origin.x) << ',' << number(mesh.origin.y) << ']' << ",\"positions\":";
  writeArray(out, mesh.positions);
  out << ",\"indices\":";
  writeArray(out, mesh.indices);
  out << "}\n";
}

bool writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out);
}

bool writeSample(const std::filesystem::path& folder, const Sample& sample) {
  const auto input = strahler::encoding::test_support::syntheticTile(
      sample.quads, sample.spacing, sample.origin, 4.0 * sample.spacing, sample.textureCoordinates);
  const auto mesh = buildGridMesh(input);
  if (!mesh.ok()) {
    std::cerr << sample.name << ": " << mesh.error().message << '\n';
    return false;
  }
  const auto drc = encodeDraco(mesh.value(), sample.options);
  const auto glb = encodeGlb(mesh.value(), sample.options);
  if (!drc.ok() || !glb.ok()) {
    std::cerr << sample.name << ": " << (drc.ok() ? glb.error() : drc.error()).message << '\n';
    return false;
  }
  writeExpected(folder / (sample.name + ".json"), sample, mesh.value());
  return writeBytes(folder / (sample.name + ".drc"), drc.value()) &&
         writeBytes(folder / (sample.name + ".glb"), glb.value());
}

std::vector<Sample> samples() {
  std::vector<Sample> list;
  // A 2×2 block of neighbouring 65×65 tiles with texture coordinates, default options.
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx)
      list.push_back({"tile_64_x" + std::to_string(tx) + "_y" + std::to_string(ty),
                      64,
                      30.0,
                      {-1920.0 + tx * 1920.0, 3840.0 + ty * 1920.0},
                      true,
                      {}});
  DracoOptions fastest;
  fastest.speed = 10; // sequential connectivity instead of Edgebreaker
  list.push_back({"tile_32_no_uv_speed10", 32, 7.5, {10000.0, -2000.0}, false, fastest});
  DracoOptions fine;
  fine.speed = 0;
  fine.maxPositionError = 0.003; // 21 bits over 3.84 km
  list.push_back({"tile_256_fine", 256, 15.0, {-3840.0, 0.0}, true, fine});
  return list;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_mesh_samples <output folder>\n";
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  std::error_code error;
  std::filesystem::remove_all(folder, error);
  std::filesystem::create_directories(folder, error);
  if (error) {
    std::cerr << "cannot create " << folder << ": " << error.message() << '\n';
    return 1;
  }
  for (const Sample& sample : samples()) {
    if (!writeSample(folder, sample))
      return 1;
    std::cout << "wrote " << (folder / sample.name).string() << ".{drc,glb,json}\n";
  }
  return 0;
}
