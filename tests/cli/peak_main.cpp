// SPDX-License-Identifier: MIT
// rastrules_test_peak PEAK_FILE COMMAND [ARGS...]: runs COMMAND and writes the peak resident set
// of that process alone (KiB, its own ru_maxrss from wait4) to PEAK_FILE; exits with its status.
//
// The CLI tests bound the memory of `rastrules render` through this small program rather than
// through getrusage(RUSAGE_CHILDREN) of the test process: Linux starts a child's peak from the
// resident set of the process it was forked from (kept at exec), so a test process that had
// grown by other tests reported their memory (and std::system's shell carried it on). Forked
// from this program, the command's peak starts from about a megabyte.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: rastrules_test_peak PEAK_FILE COMMAND [ARGS...]\n");
    return 2;
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    std::perror("rastrules_test_peak: fork");
    return 2;
  }
  if (pid == 0) {
    ::execv(argv[2], argv + 2);
    std::perror("rastrules_test_peak: execv");
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  pid_t waited = 0;
  do {
    waited = ::wait4(pid, &status, 0, &usage);
  } while (waited < 0 && errno == EINTR);
  if (waited != pid) {
    std::perror("rastrules_test_peak: wait4");
    return 2;
  }
  std::FILE* f = std::fopen(argv[1], "w");
  if (f == nullptr || std::fprintf(f, "%ld\n", usage.ru_maxrss) < 0 || std::fclose(f) != 0) {
    std::perror("rastrules_test_peak: the peak file");
    return 2;
  }
  if (WIFEXITED(status))
    return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}
