// Writes the seed corpus of fuzz_world_file into the folder given as argument: the store tests'
// synthetic worlds (tests/core/store/world_fixtures.h), each as a whole file (first byte 0)
// and as a payload for the harness to frame (first byte 1).
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
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    const std::string file =
        strahler::store::encodeWorld(strahler::store::test_support::makeSmallWorld(seed));
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
