// The world cache directory: hits, misses, and damaged or foreign files moved aside.

#include "world_fixtures.h"
#include "world_proto.h"

#include "strahler/store/world_cache.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace strahler::store {
namespace {

using base::ErrorCode;
using test_support::failsWith;
using test_support::listDir;
using test_support::makeSmallWorld;
using test_support::scratchDir;
using test_support::worldsEqual;

void overwrite(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

/// Loads `key`, expecting nullopt and a warning containing every part of `parts`.
void expectDiscarded(WorldCache& cache, const std::string& key,
                     std::initializer_list<std::string> parts) {
  std::string warning;
  auto loaded = cache.load(key, &warning);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  EXPECT_FALSE(loaded.value().has_value());
  for (const std::string& part : parts)
    EXPECT_NE(warning.find(part), std::string::npos)
        << "warning: " << warning << "\nlacks: " << part;
  const std::string path = cache.pathFor(key);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(std::filesystem::exists(path + ".corrupt"));
}

TEST(WorldCache, PathForNamesTheKeyInsideTheDirectory) {
  EXPECT_EQ(WorldCache("/var/cache/strahler").pathFor("abc123"),
            "/var/cache/strahler/abc123.world");
}

TEST(WorldCache, MissIsNullopt) {
  WorldCache cache(scratchDir() + "/not/created/yet");
  std::string warning;
  STRAHLER_ASSIGN_OR_ASSERT(auto loaded, cache.load("0123456789abcdef0123456789abcdef", &warning));
  EXPECT_FALSE(loaded.has_value());
  EXPECT_TRUE(warning.empty());
}

TEST(WorldCache, SaveThenLoadGivesTheSameWorld) {
  WorldCache cache(scratchDir() + "/nested/cache");
  const construction::WorldData world = makeSmallWorld(8);
  STRAHLER_ASSERT_OK(cache.save(world));
  std::string warning;
  STRAHLER_ASSIGN_OR_ASSERT(auto loaded, cache.load(world.cacheKey, &warning));
  ASSERT_TRUE(loaded.has_value());
  EXPECT_TRUE(worldsEqual(*loaded, world));
  EXPECT_TRUE(warning.empty());
  EXPECT_EQ(listDir(cache.dir()), std::vector<std::string>{world.cacheKey + ".world"});
}

TEST(WorldCache, CorruptFileIsReportedMovedAsideAndThenMissed) {
  WorldCache cache(scratchDir());
  const construction::WorldData world = makeSmallWorld();
  STRAHLER_ASSERT_OK(cache.save(world));
  std::string bytes = encodeWorld(world);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x01);
  overwrite(cache.pathFor(world.cacheKey), bytes);
  expectDiscarded(cache, world.cacheKey,
                  {"ignoring corrupt cached world", "checksum mismatch", "regenerating",
                   cache.pathFor(world.cacheKey) + ".corrupt"});
  std::string warning;
  STRAHLER_ASSIGN_OR_ASSERT(auto again, cache.load(world.cacheKey, &warning));
  EXPECT_FALSE(again.has_value());
  EXPECT_TRUE(warning.empty()) << warning;
}

TEST(WorldCache, TruncatedFileIsDiscarded) {
  WorldCache cache(scratchDir());
  const construction::WorldData world = makeSmallWorld();
  STRAHLER_ASSERT_OK(cache.save(world));
  overwrite(cache.pathFor(world.cacheKey), encodeWorld(world).substr(0, 100));
  expectDiscarded(cache, world.cacheKey, {"truncated or extended"});
}

TEST(WorldCache, OtherFormatVersionIsDiscarded) {
  WorldCache cache(scratchDir());
  const construction::WorldData world = makeSmallWorld();
  const std::string bytes = encodeWorld(world);
  auto payload = detail::unframe(bytes, "w"); // A view into `bytes`.
  STRAHLER_ASSERT_OK(payload);
  STRAHLER_ASSERT_OK(cache.save(world));
  overwrite(cache.pathFor(world.cacheKey), detail::frame(payload.value(), 1));
  expectDiscarded(cache, world.cacheKey,
                  {"has format version 1, this strahler reads versions 2 and 3"});
}

TEST(WorldCache, FileHoldingAnotherKeyIsDiscarded) {
  WorldCache cache(scratchDir());
  const construction::WorldData world = makeSmallWorld();
  const std::string otherKey = "fedcba9876543210fedcba9876543210";
  std::filesystem::create_directories(cache.dir());
  overwrite(cache.pathFor(otherKey), encodeWorld(world));
  expectDiscarded(cache, otherKey,
                  {"holds cache key '" + world.cacheKey + "', not '" + otherKey + "'"});
}

TEST(WorldCache, WarningMayBeOmitted) {
  WorldCache cache(scratchDir());
  const construction::WorldData world = makeSmallWorld();
  STRAHLER_ASSERT_OK(cache.save(world));
  overwrite(cache.pathFor(world.cacheKey), "garbage");
  STRAHLER_ASSIGN_OR_ASSERT(auto loaded, cache.load(world.cacheKey, nullptr));
  EXPECT_FALSE(loaded.has_value());
}

TEST(WorldCache, InvalidKeysAreRefused) {
  WorldCache cache(scratchDir());
  EXPECT_TRUE(failsWith(cache.load("../../etc/passwd", nullptr), ErrorCode::kInvalidInput,
                        "invalid world cache key '../../etc/passwd'"));
  EXPECT_TRUE(failsWith(cache.load("", nullptr), ErrorCode::kInvalidInput, "invalid"));
  construction::WorldData world = makeSmallWorld();
  world.cacheKey = "a/b";
  EXPECT_TRUE(failsWith(cache.save(world), ErrorCode::kInvalidInput, "'a/b'"));
  EXPECT_TRUE(listDir(cache.dir()).empty());
}

TEST(WorldCache, UncreatableDirectoryIsAnIoError) {
  const std::string file = scratchDir() + "/plain-file";
  overwrite(file, "not a directory");
  WorldCache cache(file + "/cache");
  EXPECT_TRUE(failsWith(cache.save(makeSmallWorld()), ErrorCode::kIoError,
                        "cannot create the world cache directory"));
}

} // namespace
} // namespace strahler::store
