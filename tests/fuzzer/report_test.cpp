// SPDX-License-Identifier: MIT
// The fuzzer's outputs appear only when complete: a write that fails part-way (here: the file
// size limit, as a full disk would) leaves no truncated picture and no temporary file.

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer {
namespace {

// rule: FUZZ.REPORT, SCENE.INPUT.ERRORS
TEST(Report, AFailedPictureWriteLeavesNoFile) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rastrules-report-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "finding.png").string();
  Scene scene;
  scene.width = scene.height = 2;
  scene.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{2, 0}, FloatPoint{0, 2}}));
  Comparison c;
  c.expected = {Fragment{0, 0, 0}, Fragment{0, 1, 0}, Fragment{0, 0, 1}};
  c.actual = {Fragment{0, 0, 0}};
  c.missing = {DiffEntry{0, 1, 0, 1}, DiffEntry{0, 0, 1, 1}};

  // In a child whose files may not exceed 512 bytes: the picture (several kilobytes) fails
  // part-way through; SIGXFSZ is ignored so that the write returns an error instead.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit small{512, 512};
    ::setrlimit(RLIMIT_FSIZE, &small);
    const auto err = write_difference_png(path, scene, c);
    ::_exit(err.has_value() ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the failed write was not reported";
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a truncated picture or temporary was left";

  // Without the limit the same picture is written whole.
  EXPECT_EQ(write_difference_png(path, scene, c), std::nullopt);
  EXPECT_GT(std::filesystem::file_size(path), 512u);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace rastrules::fuzzer
