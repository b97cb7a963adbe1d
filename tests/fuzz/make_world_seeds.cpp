// Writes the seed corpus of fuzz_world_file into the folder given as argument: the store tests'
// synthetic worlds (tests/core/store/world_fixtures.h), each as a whole file (first byte 0)
// and as a payload for the harness to frame (first byte 1); the second also with an erosion
// residual (format 3: chunks of deflated varints for the decoder to refuse when damaged).
#include "world_fixtures.h"

#include "strahler/store/world_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_world_seeds DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  std::filesystem::create_directories(dir);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    strahler::construction::WorldData world =
        strahler::store::test_support::makeSmallWorld(seed == 3 ? 2 : seed);
    if (seed == 3) { // a 128 × 64 residual: one chunk of values, one empty
      strahler::construction::ReliefResidual& r = world.relief;
      r.spacing = 60.0;
      r.column0 = -64;
      r.row0 = 0;
      r.columns = 128;
      r.rows = 64;
      r.quanta.assign(128 * 64, 0);
      for (std::size_t i = 0; i < r.quanta.size(); i += 2)
        r.quanta[i] = static_cast<std::int16_t>(static_cast<int>((i * 37) % 2000) - 1000);
    }
    const std::string file = strahler::store::encodeWorld(world);
    const std::string payload = file.substr(strahler::store::kWorldHeaderBytes,
                                            file.size() - strahler::store::kWorldHeaderBytes -
                                                strahler::store::kWorldTrailerBytes);
    const std::string stem = dir + "/small-" + std::to_string(seed);
    std::ofstream whole(stem + ".world", std::ios::binary);
    whole << '\0' << file;
    std::ofstream framed(stem + ".payload", std::ios::binary);
    framed << '\1' << payload;
    if (!whole || !framed) {
      std::fprintf(stderr, "make_world_seeds: cannot write %s.*\n", stem.c_str());
      return 1;
    }
  }
  return 0;
}
