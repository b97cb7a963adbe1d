// World files on disk: round trip, missing and oversized files, and atomic replacement.

#include "world_fixtures.h"

#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace strahler::store {
namespace {

using base::ErrorCode;
using test_support::failsWith;
using test_support::listDir;
using test_support::makeLargeWorld;
using test_support::makeSmallWorld;
using test_support::scratchDir;
using test_support::worldsEqual;

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(WorldFile, WriteThenReadRoundTrips) {
  const std::string path = scratchDir() + "/w.world";
  const construction::WorldData world = makeSmallWorld(4);
  STRAHLER_ASSERT_OK(writeWorldFile(path, world));
  EXPECT_EQ(readBytes(path), encodeWorld(world));
  STRAHLER_ASSIGN_OR_ASSERT(auto read, readWorldFile(path));
  EXPECT_TRUE(worldsEqual(read, world));
}

TEST(WorldFile, OverwritingReplacesTheFileAndLeavesNoTemporaryFile) {
  const std::string dir = scratchDir();
  const std::string path = dir + "/w.world";
  STRAHLER_ASSERT_OK(writeWorldFile(path, makeSmallWorld(1)));
  STRAHLER_ASSERT_OK(writeWorldFile(path, makeSmallWorld(2)));
  STRAHLER_ASSIGN_OR_ASSERT(auto read, readWorldFile(path));
  EXPECT_TRUE(worldsEqual(read, makeSmallWorld(2)));
  EXPECT_EQ(listDir(dir), std::vector<std::string>{"w.world"});
}

/// The PID of a process that has exited (and been reaped).
pid_t deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0)
    ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

TEST(WorldFile, StaleTemporariesOfDeadOrLongGoneWritersAreRemoved) {
  const std::string dir = scratchDir();
  const std::string dead = std::to_string(deadPid()), live = std::to_string(::getppid());
  for (const std::string& name : std::vector<std::string>{
           "a.world.tmp." + dead + ".0", "b.world.tmp." + dead + ".17",
           "c.world.tmp." + live + ".0", "d.world.tmp." + live + ".1", "e.world.tmp.x.0",
           "f.png.tmp." + dead + ".0", "g.world.tmp." + dead, "h.world"})
    std::ofstream(dir + "/" + name) << "x";
  // A live writer's file older than kStaleTemporaryAge is stale too (PID reused, or another
  // PID namespace sharing the directory).
  std::filesystem::last_write_time(dir + "/d.world.tmp." + live + ".1",
                                   std::filesystem::file_time_type::clock::now() -
                                       kStaleTemporaryAge - std::chrono::minutes(1));
  EXPECT_EQ(removeStaleWorldTemporaries(dir), 3u);
  EXPECT_EQ(listDir(dir), (std::vector<std::string>{"c.world.tmp." + live + ".0", "e.world.tmp.x.0",
                                                    "f.png.tmp." + dead + ".0",
                                                    "g.world.tmp." + dead, "h.world"}));
  EXPECT_EQ(removeStaleWorldTemporaries(dir + "/missing"), 0u);
}

TEST(WorldFile, MissingFileIsNotFound) {
  const std::string path = scratchDir() + "/absent.world";
  EXPECT_TRUE(failsWith(readWorldFile(path), ErrorCode::kNotFound, path));
}

TEST(WorldFile, DirectoryIsAnIoError) {
  const std::string dir = scratchDir();
  EXPECT_TRUE(failsWith(readWorldFile(dir), ErrorCode::kIoError, "is not a regular file"));
}

TEST(WorldFile, TruncatedFileIsCorrupt) {
  const std::string path = scratchDir() + "/cut.world";
  const std::string bytes = encodeWorld(makeSmallWorld());
  std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_TRUE(failsWith(readWorldFile(path), ErrorCode::kCorrupt, "world file '" + path + "'"));
}

TEST(WorldFile, OversizedFileIsRefusedBeforeReading) {
  const std::string path = scratchDir() + "/huge.world";
  std::ofstream(path, std::ios::binary) << "x";
  std::filesystem::resize_file(path, kMaxWorldFileBytes + 1); // Sparse: no disk used.
  EXPECT_TRUE(failsWith(readWorldFile(path), ErrorCode::kCorrupt,
                        "world file '" + path + "' is 1073741825 bytes, more than the limit"));
}

TEST(WorldFile, MissingDirectoryIsAnIoErrorNamingThePath) {
  const std::string path = scratchDir() + "/no/such/dir/w.world";
  EXPECT_TRUE(failsWith(writeWorldFile(path, makeSmallWorld()), ErrorCode::kIoError,
                        "'" + path + "': No such file or directory"));
}

/// Limits the size of any file this process writes, and restores the limit on exit.
class FileSizeLimit {
public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    savedHandler_ = std::signal(SIGXFSZ, SIG_IGN); // write() then fails with EFBIG.
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limited);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, savedHandler_);
  }

private:
  rlimit saved_{};
  void (*savedHandler_)(int) = nullptr;
};

TEST(WorldFile, FailedWriteLeavesTheTargetIntactAndNoTemporaryFile) {
  const std::string dir = scratchDir();
  const std::string path = dir + "/w.world";
  const construction::WorldData old = makeSmallWorld(1);
  STRAHLER_ASSERT_OK(writeWorldFile(path, old));
  base::Status status = base::Ok{};
  {
    const FileSizeLimit limit(4096); // The large world needs far more.
    status = writeWorldFile(path, makeLargeWorld(100.0));
  }
  EXPECT_TRUE(failsWith(status, ErrorCode::kIoError, "cannot write a temporary file for '" + path));
  EXPECT_EQ(listDir(dir), std::vector<std::string>{"w.world"});
  STRAHLER_ASSIGN_OR_ASSERT(auto read, readWorldFile(path));
  EXPECT_TRUE(worldsEqual(read, old));
}

TEST(WorldFile, FailedRenameRemovesTheTemporaryFile) {
  const std::string dir = scratchDir();
  const std::string path = dir + "/taken.world";
  std::filesystem::create_directories(path + "/inside"); // rename() cannot replace it.
  EXPECT_TRUE(failsWith(writeWorldFile(path, makeSmallWorld()), ErrorCode::kIoError,
                        "cannot rename the temporary file over '" + path + "'"));
  EXPECT_EQ(listDir(dir), std::vector<std::string>{"taken.world"});
  EXPECT_TRUE(std::filesystem::is_directory(path + "/inside"));
}

TEST(WorldFile, UnwritableDirectoryKeepsTheOldFile) {
  if (::geteuid() == 0)
    GTEST_SKIP() << "root ignores directory permissions";
  const std::string dir = scratchDir();
  const std::string path = dir + "/w.world";
  STRAHLER_ASSERT_OK(writeWorldFile(path, makeSmallWorld(1)));
  ::chmod(dir.c_str(), 0555);
  const base::Status status = writeWorldFile(path, makeSmallWorld(2));
  ::chmod(dir.c_str(), 0755);
  EXPECT_TRUE(failsWith(status, ErrorCode::kIoError, path));
  EXPECT_EQ(listDir(dir), std::vector<std::string>{"w.world"});
  STRAHLER_ASSIGN_OR_ASSERT(auto read, readWorldFile(path));
  EXPECT_TRUE(worldsEqual(read, makeSmallWorld(1)));
}

} // namespace
} // namespace strahler::store
