// SPDX-License-Identifier: MIT
// The external-process driver (spec/driver.md DRIVER.EXTERNAL.PROTOCOL).
// Implements: DRIVER.EXTERNAL.PROTOCOL

#include "rastrules/driver/external.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <thread>
#include <tuple>

#include <nlohmann/json.hpp>

#include "drivers.hpp"
#include "rastrules/io/interrupt.hpp"
#include "rastrules/io/scene_json.hpp"

extern char** environ;

namespace rastrules::driver {
namespace {

constexpr std::size_t kMaxStderrBytes = 4096;

struct ProcessResult {
  std::string spawn_error; // non-empty: the process could not be started
  bool timed_out = false;
  bool output_overflow = false;
  bool exited = false;
  int exit_status = 0;
  int signal = 0;
  std::string out;
  std::string err;
};

void close_fd(int& fd) {
  if (fd >= 0)
    ::close(fd);
  fd = -1;
}

// Waits until the deadline for process pid (the leader of its own group, both outputs closed)
// to exit. The exit is seen without reaping the process (WNOWAIT), so that its group can still
// be named safely: what it left running in the background is killed before the process is
// reaped. Returns its wait status, or nullopt when the deadline came first (it still runs).
// rule: DRIVER.EXTERNAL.PROTOCOL
std::optional<int> wait_and_end_group(pid_t pid, std::chrono::steady_clock::time_point deadline) {
  while (true) {
    siginfo_t info{};
    const int w = ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT);
    if (w == 0 && info.si_pid == pid) {
      io::set_driver_group(0);
      ::kill(-pid, SIGKILL); // the group's other members (a process that called setsid escapes)
      int status = 0;
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      return status;
    }
    if (w < 0 && errno != EINTR)
      return 0; // no such child: nothing left to wait for
    if (std::chrono::steady_clock::now() >= deadline)
      return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// Runs argv with `input` on its standard input, collecting standard output (at most
// max_output bytes) and the first bytes of standard error, killing it (and its process group)
// after timeout_ms.
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& input,
                          const ExternalOptions& options) {
  ProcessResult r;
  int in_pipe[2] = {-1, -1}, out_pipe[2] = {-1, -1}, err_pipe[2] = {-1, -1};
  if (::pipe2(in_pipe, O_CLOEXEC) != 0 || ::pipe2(out_pipe, O_CLOEXEC) != 0 ||
      ::pipe2(err_pipe, O_CLOEXEC) != 0) {
    r.spawn_error = std::string("pipe: ") + std::strerror(errno);
    for (int* p : {in_pipe, out_pipe, err_pipe}) {
      close_fd(p[0]);
      close_fd(p[1]);
    }
    return r;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in_pipe[0], 0);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], 1);
  posix_spawn_file_actions_adddup2(&actions, err_pipe[1], 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setpgroup(&attr, 0); // its own group, so that a timeout kills its children too
  sigset_t default_signals;
  sigemptyset(&default_signals);
  sigaddset(&default_signals, SIGPIPE);
  posix_spawnattr_setsigdefault(&attr, &default_signals);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> args;
  for (const std::string& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  close_fd(in_pipe[0]);
  close_fd(out_pipe[1]);
  close_fd(err_pipe[1]);
  if (rc != 0) {
    r.spawn_error = "cannot start \"" + argv[0] + "\": " + std::strerror(rc);
    close_fd(in_pipe[1]);
    close_fd(out_pipe[0]);
    close_fd(err_pipe[0]);
    return r;
  }
  for (int fd : {in_pipe[1], out_pipe[0], err_pipe[0]})
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  io::set_driver_group(pid); // an interrupt of rastrules ends the driver's group too
  struct ForgetGroup {
    ~ForgetGroup() { io::set_driver_group(0); }
  } forget_group;

  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(options.timeout_ms);
  std::size_t written = 0;
  if (input.empty())
    close_fd(in_pipe[1]);
  bool kill_it = false;
  while (out_pipe[0] >= 0 || err_pipe[0] >= 0) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) {
      r.timed_out = true;
      kill_it = true;
      break;
    }
    std::vector<pollfd> fds;
    if (in_pipe[1] >= 0)
      fds.push_back({in_pipe[1], POLLOUT, 0});
    if (out_pipe[0] >= 0)
      fds.push_back({out_pipe[0], POLLIN, 0});
    if (err_pipe[0] >= 0)
      fds.push_back({err_pipe[0], POLLIN, 0});
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count();
    const int n = ::poll(fds.data(), static_cast<nfds_t>(fds.size()),
                         static_cast<int>(std::min<long long>(left + 1, 1000)));
    if (n < 0 && errno != EINTR)
      break;
    for (const pollfd& p : fds) {
      if (p.revents == 0)
        continue;
      if (p.fd == in_pipe[1]) {
        if ((p.revents & (POLLERR | POLLHUP)) != 0) {
          close_fd(in_pipe[1]); // the process closed its standard input: stop writing
          continue;
        }
        const ssize_t w = ::write(in_pipe[1], input.data() + written, input.size() - written);
        if (w > 0)
          written += static_cast<std::size_t>(w);
        if ((w < 0 && errno != EAGAIN && errno != EINTR) || written == input.size())
          close_fd(in_pipe[1]);
        continue;
      }
      char buf[65536];
      const ssize_t got = ::read(p.fd, buf, sizeof buf);
      if (got == 0 || (got < 0 && errno != EAGAIN && errno != EINTR)) {
        if (p.fd == out_pipe[0])
          close_fd(out_pipe[0]);
        else
          close_fd(err_pipe[0]);
        continue;
      }
      if (got < 0)
        continue;
      const auto g = static_cast<std::size_t>(got);
      if (p.fd == out_pipe[0]) {
        if (r.out.size() + g > options.max_output_bytes) {
          r.output_overflow = true;
          kill_it = true;
          break;
        }
        r.out.append(buf, g);
      } else if (r.err.size() < kMaxStderrBytes) {
        r.err.append(buf, std::min(g, kMaxStderrBytes - r.err.size()));
      }
    }
    if (kill_it)
      break;
  }
  close_fd(in_pipe[1]);
  close_fd(out_pipe[0]);
  close_fd(err_pipe[0]);
  int status = 0;
  if (!kill_it) {
    if (const auto exited = wait_and_end_group(pid, deadline)) {
      r.exited = WIFEXITED(*exited);
      r.exit_status = r.exited ? WEXITSTATUS(*exited) : 0;
      r.signal = WIFSIGNALED(*exited) ? WTERMSIG(*exited) : 0;
      return r;
    }
    r.timed_out = true;
  }
  io::set_driver_group(0);
  ::kill(-pid, SIGKILL);
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return r;
}

std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r' || c == '\t')
      c = ' ';
  }
  while (!s.empty() && s.back() == ' ')
    s.pop_back();
  return io::printable(s, 300);
}

// rule: DRIVER.EXTERNAL.PROTOCOL
class ExternalDriver final : public Driver {
public:
  ExternalDriver(std::string command, ExternalOptions options)
      : argv_(external_argv(command)), options_(options),
        info_(detail::full_capabilities("external", command, -1)) {
    // A process that exits without reading its input must not kill us with SIGPIPE.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, nullptr);
  }

  [[nodiscard]] const DriverInfo& info() const override { return info_; }
  [[nodiscard]] std::string unsupported(const Scene&) const override { return {}; }

  [[nodiscard]] DrawResult draw(const Scene& scene) override {
    const std::string& cmd = info_.description;
    const ProcessResult r = run_process(argv_, io::write_scene(scene), options_);
    if (!r.spawn_error.empty())
      return DriverError{"external driver: " + r.spawn_error};
    const std::string err = r.err.empty() ? "" : "; its standard error: " + one_line(r.err);
    if (r.timed_out) {
      return DriverError{"external driver \"" + cmd + "\" timed out after " +
                         std::to_string(options_.timeout_ms) + " ms and was killed" + err};
    }
    if (r.output_overflow) {
      return DriverError{"external driver \"" + cmd + "\" wrote more than " +
                         std::to_string(options_.max_output_bytes) +
                         " bytes on standard output and was killed"};
    }
    if (r.signal != 0) {
      const char* name = ::strsignal(r.signal);
      return DriverError{"external driver \"" + cmd + "\" crashed: killed by signal " +
                         std::to_string(r.signal) + " (" + (name != nullptr ? name : "?") + ")" +
                         err};
    }
    if (!r.exited || r.exit_status != 0) {
      return DriverError{"external driver \"" + cmd + "\" exited with status " +
                         std::to_string(r.exit_status) + err};
    }
    auto parsed = parse_external_fragments(r.out, scene);
    if (auto* e = std::get_if<std::string>(&parsed)) {
      return DriverError{"external driver \"" + cmd + "\": malformed output: " + *e};
    }
    return std::get<std::vector<Fragment>>(std::move(parsed));
  }

private:
  std::vector<std::string> argv_;
  ExternalOptions options_;
  DriverInfo info_;
};

std::optional<std::int64_t> get_int(const nlohmann::json& v) {
  if (v.is_number_integer())
    return v.get<std::int64_t>();
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u <= static_cast<std::uint64_t>(INT64_MAX))
      return static_cast<std::int64_t>(u);
  }
  return std::nullopt;
}

} // namespace

ExternalOptions default_external_options(std::string* error) {
  ExternalOptions o;
  const char* t = std::getenv("RASTRULES_EXTERNAL_TIMEOUT_MS");
  if (t == nullptr)
    return o;
  const std::string_view text(t);
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc{} && end == text.data() + text.size() && v >= 1 &&
      v <= kMaxExternalTimeoutMs) {
    o.timeout_ms = v;
  } else if (error != nullptr) {
    *error = "RASTRULES_EXTERNAL_TIMEOUT_MS needs an integer in [1, " +
             std::to_string(kMaxExternalTimeoutMs) + "] (milliseconds), got \"" +
             io::printable(text, 40) + "\"";
  }
  return o;
}

std::vector<std::string> external_argv(std::string_view command) {
  const auto plain = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::strchr("_-./:=,+@% \t", c) != nullptr;
  };
  if (!std::all_of(command.begin(), command.end(), plain))
    return {"/bin/sh", "-c", std::string(command)};
  std::vector<std::string> argv;
  std::string word;
  for (const char c : command) {
    if (c == ' ' || c == '\t') {
      if (!word.empty())
        argv.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty())
    argv.push_back(word);
  return argv;
}

namespace {

constexpr std::size_t kMaxProtocolDepth = 8;

// Returns the deepest nesting of arrays and objects in text, outside strings (a scan that
// tolerates malformed text: the parser reports what is wrong with it).
std::size_t max_nesting_depth(std::string_view text) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

} // namespace

// rule: DRIVER.EXTERNAL.PROTOCOL
std::variant<std::vector<Fragment>, std::string> parse_external_fragments(std::string_view text,
                                                                          const Scene& scene) {
  // The protocol nests 4 deep ({"fragments": [{"centroid": [...]}]}); the DOM parser recurses
  // once per level, so deeper text is refused before parsing rather than risk the stack.
  if (const std::size_t depth = max_nesting_depth(text); depth > kMaxProtocolDepth) {
    return "nesting deeper than " + std::to_string(kMaxProtocolDepth) + " levels (" +
           std::to_string(depth) + ")";
  }
  if (auto nul = io::nul_byte_problem(text))
    return "not JSON: " + *nul;
  // A key given twice would silently keep the last value (a fragment list could become empty):
  // every object's keys are tracked while parsing and the first repeat is reported.
  std::vector<std::set<std::string>> keys;
  std::string duplicate;
  const nlohmann::json::parser_callback_t track = [&](int, nlohmann::json::parse_event_t event,
                                                      nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (event == E::object_start)
      keys.emplace_back();
    else if (event == E::object_end && !keys.empty())
      keys.pop_back();
    else if (event == E::key && !keys.empty() &&
             !keys.back().insert(parsed.get<std::string>()).second && duplicate.empty())
      duplicate = parsed.get<std::string>();
    return true;
  };
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text.begin(), text.end(), track);
  } catch (const nlohmann::json::parse_error& e) {
    return std::string("not JSON: ") + e.what();
  } catch (const nlohmann::json::exception& e) { // e.g. a number too large for any type
    return std::string("not JSON the protocol allows: ") + e.what();
  }
  if (!duplicate.empty())
    return "the key \"" + io::printable(duplicate, 40) + "\" is given twice in one object";
  if (!doc.is_object() || !doc.contains("fragments") || !doc["fragments"].is_array()) {
    return std::string("expected {\"fragments\": [...]}");
  }
  for (const auto& [key, value] : doc.items()) {
    if (key != "fragments")
      return io::printable(key, 40) + ": unknown key (expected fragments)";
    (void)value;
  }
  const std::uint32_t samples = scene.msaa.count();
  std::vector<Fragment> out;
  std::set<std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::int64_t, std::int64_t>> seen;
  const auto& list = doc["fragments"];
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto& f = list[i];
    const std::string at = "fragments[" + std::to_string(i) + "]";
    if (!f.is_object())
      return at + ": must be an object";
    for (const auto& [key, value] : f.items()) {
      static const std::set<std::string> known = {"prim",     "x",      "y",      "mask",
                                                  "seg",      "sample", "helper", "coverage",
                                                  "centroid", "ddx",    "ddy"};
      if (known.count(key) == 0)
        return at + "." + key + ": unknown key";
      (void)value;
    }
    Fragment frag;
    for (const char* key : {"prim", "x", "y"}) {
      if (!f.contains(key))
        return at + "." + key + ": missing";
      if (!get_int(f[key]))
        return at + "." + key + ": must be an integer";
    }
    const std::int64_t prim = *get_int(f["prim"]), x = *get_int(f["x"]), y = *get_int(f["y"]);
    if (prim < 0 || prim >= static_cast<std::int64_t>(scene.primitives.size())) {
      return at + ".prim: " + std::to_string(prim) + " is not a primitive of the scene (" +
             std::to_string(scene.primitives.size()) + " primitives)";
    }
    if (x < 0 || x >= scene.width)
      return at + ".x: " + std::to_string(x) + " is outside the target (width " +
             std::to_string(scene.width) + ")";
    if (y < 0 || y >= scene.height)
      return at + ".y: " + std::to_string(y) + " is outside the target (height " +
             std::to_string(scene.height) + ")";
    std::int64_t mask = 1;
    if (f.contains("mask")) {
      const auto m = get_int(f["mask"]);
      if (!m)
        return at + ".mask: must be an integer";
      mask = *m;
    }
    if (mask < 0 || mask > static_cast<std::int64_t>(full_mask(samples))) {
      return at + ".mask: " + std::to_string(mask) + " has bits beyond the " +
             std::to_string(samples) + " sample(s) of the scene";
    }
    std::int64_t seg = -1, sample = -1;
    if (f.contains("seg")) {
      const auto s = get_int(f["seg"]);
      if (!s || *s < 0 || *s > UINT32_MAX)
        return at + ".seg: must be a non-negative integer";
      seg = *s;
      frag.seg = static_cast<std::uint32_t>(*s);
    }
    if (f.contains("sample")) {
      const auto s = get_int(f["sample"]);
      if (!s || *s < 0 || *s >= samples)
        return at + ".sample: must be a sample index below " + std::to_string(samples);
      sample = *s;
      frag.sample = static_cast<std::uint32_t>(*s);
    }
    if (f.contains("helper")) {
      if (!f["helper"].is_boolean())
        return at + ".helper: must be true or false";
      frag.helper = f["helper"].get<bool>();
    }
    frag.prim = static_cast<std::uint32_t>(prim);
    frag.x = static_cast<std::int32_t>(x);
    frag.y = static_cast<std::int32_t>(y);
    frag.mask = static_cast<std::uint32_t>(mask);
    if (!seen.emplace(frag.prim, frag.x, frag.y, seg, sample).second) {
      return at + ": duplicate fragment (prim " + std::to_string(prim) + ", x " +
             std::to_string(x) + ", y " + std::to_string(y) + ")";
    }
    out.push_back(frag);
  }
  std::stable_sort(out.begin(), out.end(), fragment_before);
  return out;
}

std::unique_ptr<Driver> open_external_driver(std::string_view command, std::string* error,
                                             ExternalOptions options) {
  if (external_argv(command).empty()) {
    if (error != nullptr)
      *error = "external driver: empty command (use external:COMMAND)";
    return nullptr;
  }
  return std::make_unique<ExternalDriver>(std::string(command), options);
}

namespace detail {
std::unique_ptr<Driver> open_external(std::string_view arg, std::string* error) {
  std::string bad;
  ExternalOptions options = default_external_options(&bad);
  if (!bad.empty()) {
    if (error != nullptr)
      *error = bad;
    return nullptr;
  }
  return open_external_driver(arg, error, options);
}
} // namespace detail

} // namespace rastrules::driver
