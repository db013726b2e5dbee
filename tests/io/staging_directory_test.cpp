// StagingDirectory's shared lock (spec/distributed.md D18): when it cannot
// be taken the directory says why, as a warning naming the directory and the
// system's reason, instead of holding no lock in silence. Root is not stopped
// by a directory's permissions, so the failures are forced otherwise: the
// open of a path that is not a directory (adopt), and the open with every
// descriptor the process may have in use (make, RLIMIT_NOFILE lowered).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "staging_directory.h"

namespace bccmis::cli {
namespace {

namespace fs = std::filesystem;

// A fresh directory under the system's temporary directory, removed after.
class StagingDirectoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = (fs::temp_directory_path() / "bccmis-staging-test-XXXXXX").string();
    ASSERT_NE(::mkdtemp(name.data()), nullptr) << std::strerror(errno);
    dir_ = name;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

//= spec/distributed.md D18 type=test
TEST_F(StagingDirectoryTest, MadeAndLockedWithoutWarning) {
  const auto staging = StagingDirectory::make((dir_ / "out").string());
  EXPECT_TRUE(staging->warning().empty()) << staging->warning();
  // The run's shared lock holds it: a later run's clean leaves it.
  const auto lines = clean_stale_staging((dir_ / "out").string());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find(": left by process "), std::string::npos) << lines[0];
  EXPECT_TRUE(fs::is_directory(staging->path()));
}

//= spec/distributed.md D18 type=test
TEST_F(StagingDirectoryTest, AdoptingWhatIsNotADirectoryWarnsWithTheReason) {
  const std::string file = (dir_ / "not-a-directory").string();
  std::ofstream(file) << "x";
  const auto staging = StagingDirectory::adopt(file);
  EXPECT_EQ(staging->warning(), file +
                                    ": cannot lock the staging directory (a run of the same outputs may take it for "
                                    "an interrupted run's and remove it): " +
                                    std::strerror(ENOTDIR));
}

//= spec/distributed.md D18 type=test
TEST_F(StagingDirectoryTest, MadeWithoutAFreeDescriptorWarnsWithTheReason) {
  rlimit before{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &before), 0);
  // The lowest free descriptor becomes the limit: every one below is in use,
  // so the directory's open fails with EMFILE (mkdtemp takes none).
  const int lowest = ::dup(0);
  ASSERT_GE(lowest, 0);
  ::close(lowest);
  rlimit low = before;
  low.rlim_cur = static_cast<rlim_t>(lowest);
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &low), 0);
  const auto staging = StagingDirectory::make((dir_ / "out").string());
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &before), 0);
  const std::string& warning = staging->warning();
  EXPECT_EQ(warning.rfind(staging->path() + ": cannot lock the staging directory (", 0), 0u) << warning;
  EXPECT_NE(warning.find(std::string("): ") + std::strerror(EMFILE)), std::string::npos) << warning;
  // What the warning is about: nothing holds it, so a later run's clean
  // takes it for an interrupted run's and removes it under this one.
  const auto lines = clean_stale_staging((dir_ / "out").string());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "removed " + staging->path() + ", left by an interrupted run");
  EXPECT_FALSE(fs::exists(staging->path()));
}

}  // namespace
}  // namespace bccmis::cli
