// SPDX-License-Identifier: MIT
// Interrupts (issue 17 item 5): SIGINT or SIGTERM in the middle of a render removes its
// temporary outputs and exits 130; in the middle of a campaign it ends the external driver's
// process group, writes the report of the cases so far and exits 130.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "rastrules/io/interrupt.hpp"
#include "rastrules/io/scene_json.hpp"
#include "support.hpp"

extern char** environ;

namespace rastrules::test {
namespace {

// Starts rastrules with args, its standard output to out_path; returns its pid.
pid_t start(const std::vector<std::string>& args, const std::filesystem::path& out_path) {
  std::vector<std::string> all = {RASTRULES_CLI};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  EXPECT_EQ(::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits up to 20 s for `ready`; returns whether it came.
template <class Ready> bool wait_for(Ready ready) {
  for (int i = 0; i < 2000; ++i) {
    if (ready())
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

int exit_status(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool has_temporary(const std::filesystem::path& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().rfind(".rastrules-", 0) == 0)
      return true;
  return false;
}

// rule: SCENE.INPUT.ERRORS
TEST(CliInterrupt, ARenderRemovesItsTemporariesAndExits130) {
  for (const int sig : {SIGINT, SIGTERM}) {
    const TempDir dir;
    std::string prims;
    for (int i = 0; i < 64; ++i)
      prims += std::string(i ? ", " : "") +
               R"({"type": "triangle", "v": [[0, 0], [4096, 0], [0, 4096]]})";
    const auto scene =
        dir.write("big.json",
                  R"({"target": {"width": 2048, "height": 2048}, "primitives": [)" + prims + "]}");
    const auto out = dir.write("out.json", "keep me");
    const pid_t pid =
        start({"render", scene.string(), "--fragments", out.string(), "--png",
               (dir / "p.png").string(), "--scale", "1", "--max-fragments", "1099511627776"},
              dir / "stdout");
    ASSERT_TRUE(wait_for([&] { return has_temporary(dir.path()); })) << "no temporary appeared";
    ::kill(pid, sig);
    EXPECT_EQ(exit_status(pid), 130) << sig;
    EXPECT_FALSE(has_temporary(dir.path())) << sig;
    EXPECT_EQ(read_file(out), "keep me");
    EXPECT_FALSE(std::filesystem::exists(dir / "p.png"));
  }
}

// rule: SCENE.INPUT.ERRORS, FUZZ.REPORT, DRIVER.EXTERNAL.PROTOCOL
TEST(CliInterrupt, ACampaignEndsTheDriverWritesItsReportAndExits130) {
  const TempDir dir;
  const auto group_file = dir / "group";
  const auto driver =
      dir.write("hang.sh", "#!/bin/sh\necho $$ > " + group_file.string() + "\nexec sleep 300\n");
  std::filesystem::permissions(driver, std::filesystem::perms::owner_all);
  const pid_t pid = start({"fuzz", "--driver", "external:" + driver.string(), "--cases", "5",
                           "--out", (dir / "out").string()},
                          dir / "stdout");
  ASSERT_TRUE(wait_for([&] { return !read_file(group_file).empty(); })) << "no driver started";
  const pid_t group = std::stoi(read_file(group_file));
  ::kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), 130);
  EXPECT_TRUE(wait_for([&] { return ::kill(-group, 0) != 0 && errno == ESRCH; }))
      << "the driver's group outlived the campaign";
  EXPECT_NE(read_file(dir / "stdout").find("result      interrupted after"), std::string::npos)
      << read_file(dir / "stdout");
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "report.json"));
}

// rule: SCENE.INPUT.ERRORS, FUZZ.PATH.REPORT
TEST(CliInterrupt, A2dCampaignStopsBetweenCasesWritesItsReportAndExits130) {
  const TempDir dir;
  const pid_t pid = start({"fuzz2d", "--driver", "imprecise-path:float-accumulation", "--cases",
                           "100000000", "--out", (dir / "out").string()},
                          dir / "stdout");
  // The first finding's scene appears once the campaign is under way.
  ASSERT_TRUE(wait_for([&] {
    return std::filesystem::exists(dir / "out") && !std::filesystem::is_empty(dir / "out");
  })) << "the campaign did not start";
  ::kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), 130);
  EXPECT_NE(read_file(dir / "stdout").find("result      interrupted after"), std::string::npos)
      << read_file(dir / "stdout");
  EXPECT_NE(read_file(dir / "out" / "report.json").find("\"interrupted\": true"),
            std::string::npos);
}

// rule: SCENE.INPUT.ERRORS
// A scene file is mapped (open_scene_file); another process truncating it while it is read
// raises SIGBUS, which the command line's handler turns into a one-line error and exit 2
// (bad input), removing the temporaries as an interrupt does.
TEST(CliInterruptDeathTest, AMappedSceneThatShrinksIsBadInputNotACrash) {
  const TempDir dir;
  const auto scene = dir.write("s.json", std::string(1 << 16, ' ') + "{}");
  const auto temporary = dir.write(".rastrules-out", "partial");
  EXPECT_EXIT(
      {
        io::handle_interrupts(io::OnInterrupt::kExit);
        (void)io::register_temporary(temporary.string());
        auto text = io::open_scene_file(scene.string());
        auto* t = std::get_if<io::SceneText>(&text);
        if (t == nullptr || !t->mapped())
          std::_Exit(3);
        std::filesystem::resize_file(scene, 0);
        volatile char last = t->view().back(); // the page is gone: SIGBUS
        (void)last;
        std::_Exit(4);
      },
      ::testing::ExitedWithCode(io::kExitTruncatedInput),
      "rastrules: error: the scene file shrank while it was being read");
  EXPECT_FALSE(std::filesystem::exists(temporary));
}

} // namespace
} // namespace rastrules::test
