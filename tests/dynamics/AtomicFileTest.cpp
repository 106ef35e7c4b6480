#include "dynamics/io/AtomicFile.h"
#include "dynamics/core/Errors.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace rv {
namespace {

namespace fs = std::filesystem;

TEST(AtomicFile, AppearsOnlyOnCommitAndLeavesNothingOtherwise) {
  const fs::path dir = fs::temp_directory_path() / ("rv-atomic-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string target = (dir / "out.csv").string();
  {
    AtomicFile f(target, "-o");
    std::ofstream(f.tempPath()) << "half";
    EXPECT_FALSE(fs::exists(target));
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_TRUE(fs::is_empty(dir)) << "the abandoned temporary is removed";
  {
    AtomicFile f(target, "-o");
    std::ofstream(f.tempPath()) << "whole";
    f.commit();
  }
  std::string content;
  std::ifstream(target) >> content;
  EXPECT_EQ(content, "whole");
  fs::remove_all(dir);
}

TEST(AtomicFile, UnwritablePlacesAreInputErrorsNamingTheFlag) {
  try {
    AtomicFile f("/no/such/folder/out.png", "-o");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("-o /no/such/folder/out.png"), std::string::npos);
  }
  EXPECT_THROW(checkWritable(fs::temp_directory_path().string(), "-o"), InputError);
}

} // namespace
} // namespace rv
