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
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <thread>

#include "drivers.hpp"
#include "path_library.hpp"
#include "rastrules/io/interrupt.hpp"
#include "rastrules/io/json_stream.hpp"
#include "rastrules/io/scene_json.hpp"

extern char** environ;

namespace rastrules::driver {
namespace {

constexpr std::size_t kMaxStderrBytes = 4096;

// How the process ended.
struct ProcessResult {
  bool timed_out = false;
  bool output_overflow = false;
  bool exited = false;
  int exit_status = 0;
  int signal = 0;
  std::string err; // the first kMaxStderrBytes of its standard error
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

// One run of the driver's command: argv gets `input` on its standard input, its standard output
// is handed out piece by piece as it comes (next_output), at most max_output_bytes in all, and
// the first bytes of its standard error are kept; after timeout_ms it is killed with its process
// group. The deadline covers the reading of the output too, which runs between the pieces.
// rule: DRIVER.EXTERNAL.PROTOCOL
class DriverProcess {
public:
  // extra_env: one more "NAME=VALUE" for the process's environment (the capabilities query's).
  DriverProcess(const std::vector<std::string>& argv, const std::string& input,
                const ExternalOptions& options, const char* extra_env = nullptr)
      : input_(input), options_(options), deadline_(std::chrono::steady_clock::now() +
                                                    std::chrono::milliseconds(options.timeout_ms)) {
    int in_pipe[2] = {-1, -1}, out_pipe[2] = {-1, -1}, err_pipe[2] = {-1, -1};
    if (::pipe2(in_pipe, O_CLOEXEC) != 0 || ::pipe2(out_pipe, O_CLOEXEC) != 0 ||
        ::pipe2(err_pipe, O_CLOEXEC) != 0) {
      spawn_error_ = std::string("pipe: ") + std::strerror(errno);
      for (int* p : {in_pipe, out_pipe, err_pipe}) {
        close_fd(p[0]);
        close_fd(p[1]);
      }
      return;
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
    std::vector<char*> env;
    for (char** e = environ; *e != nullptr; ++e)
      env.push_back(*e);
    if (extra_env != nullptr)
      env.push_back(const_cast<char*>(extra_env));
    env.push_back(nullptr);
    const int rc = ::posix_spawnp(&pid_, args[0], &actions, &attr, args.data(), env.data());
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close_fd(in_pipe[0]);
    close_fd(out_pipe[1]);
    close_fd(err_pipe[1]);
    in_ = in_pipe[1];
    out_ = out_pipe[0];
    err_ = err_pipe[0];
    if (rc != 0) {
      spawn_error_ = "cannot start \"" + argv[0] + "\": " + std::strerror(rc);
      pid_ = 0;
      close_all();
      return;
    }
    for (int fd : {in_, out_, err_})
      ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    io::set_driver_group(pid_); // an interrupt of rastrules ends the driver's group too
    if (input_.empty())
      close_fd(in_);
  }

  DriverProcess(const DriverProcess&) = delete;
  DriverProcess& operator=(const DriverProcess&) = delete;

  ~DriverProcess() {
    if (pid_ > 0) // not finished (an exception): end it all the same
      kill_group();
    close_all();
  }

  // Non-empty: the process could not be started.
  [[nodiscard]] const std::string& spawn_error() const { return spawn_error_; }

  // Returns the next bytes the process wrote on its standard output (valid until the next
  // call), writing its input and reading its standard error meanwhile; an empty view when its
  // standard output is closed, the deadline has passed, or more than max_output_bytes came.
  std::string_view next_output() {
    std::string_view piece;
    while (out_ >= 0 && !stopped_ && piece.empty())
      pump(piece);
    return piece;
  }

  // Reads what is left of both outputs (standard output is counted against max_output_bytes
  // and dropped), waits for the process to exit and ends its group; kills it at the deadline.
  ProcessResult finish() {
    std::string_view dropped;
    while ((out_ >= 0 || err_ >= 0) && !stopped_)
      pump(dropped);
    close_all();
    if (!stopped_) {
      if (const auto status = wait_and_end_group(pid_, deadline_)) {
        result_.exited = WIFEXITED(*status);
        result_.exit_status = result_.exited ? WEXITSTATUS(*status) : 0;
        result_.signal = WIFSIGNALED(*status) ? WTERMSIG(*status) : 0;
        pid_ = 0;
        return result_;
      }
      result_.timed_out = true;
    }
    kill_group();
    return result_;
  }

private:
  // One wait for the pipes (at most until the deadline): writes what the input pipe takes,
  // keeps standard error's first bytes, and sets `piece` to what standard output gave.
  void pump(std::string_view& piece) {
    piece = {};
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline_) {
      result_.timed_out = true;
      stopped_ = true;
      return;
    }
    std::vector<pollfd> fds;
    if (in_ >= 0)
      fds.push_back({in_, POLLOUT, 0});
    if (out_ >= 0)
      fds.push_back({out_, POLLIN, 0});
    if (err_ >= 0)
      fds.push_back({err_, POLLIN, 0});
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - now).count();
    const int n = ::poll(fds.data(), static_cast<nfds_t>(fds.size()),
                         static_cast<int>(std::min<long long>(left + 1, 1000)));
    if (n < 0 && errno != EINTR) {
      close_all(); // poll itself failed: treat the outputs as ended
      return;
    }
    for (const pollfd& p : fds) {
      if (p.revents == 0)
        continue;
      if (p.fd == in_) {
        if ((p.revents & (POLLERR | POLLHUP)) != 0) {
          close_fd(in_); // the process closed its standard input: stop writing
          continue;
        }
        const ssize_t w = ::write(in_, input_.data() + written_, input_.size() - written_);
        if (w > 0)
          written_ += static_cast<std::size_t>(w);
        if ((w < 0 && errno != EAGAIN && errno != EINTR) || written_ == input_.size())
          close_fd(in_);
        continue;
      }
      const bool is_out = p.fd == out_;
      char* const into = is_out ? out_buf_.data() : err_buf_.data();
      const ssize_t got = ::read(p.fd, into, is_out ? out_buf_.size() : err_buf_.size());
      if (got == 0 || (got < 0 && errno != EAGAIN && errno != EINTR)) {
        close_fd(is_out ? out_ : err_);
        continue;
      }
      if (got < 0)
        continue;
      const auto g = static_cast<std::size_t>(got);
      if (is_out) {
        if (out_bytes_ + g > options_.max_output_bytes) {
          result_.output_overflow = true;
          stopped_ = true;
          return;
        }
        out_bytes_ += g;
        piece = std::string_view(into, g);
      } else if (result_.err.size() < kMaxStderrBytes) {
        result_.err.append(into, std::min(g, kMaxStderrBytes - result_.err.size()));
      }
    }
  }

  void close_all() {
    close_fd(in_);
    close_fd(out_);
    close_fd(err_);
  }

  void kill_group() {
    close_all();
    io::set_driver_group(0);
    ::kill(-pid_, SIGKILL);
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = 0;
  }

  const std::string& input_;
  const ExternalOptions& options_;
  const std::chrono::steady_clock::time_point deadline_;
  std::string spawn_error_;
  pid_t pid_ = 0;
  int in_ = -1, out_ = -1, err_ = -1;
  std::size_t written_ = 0;   // bytes of input written
  std::size_t out_bytes_ = 0; // bytes of standard output read
  bool stopped_ = false;      // timed out or too much output: the process is to be killed
  ProcessResult result_;
  std::array<char, 65536> out_buf_{};
  std::array<char, 4096> err_buf_{};
};

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
  // name: "external", or the name of a driver run through the protocol ("skia"); argv: what is
  // run; command: argv as the user reads it (the description, and in error messages).
  ExternalDriver(std::string name, std::vector<std::string> argv, const std::string& command,
                 ExternalOptions options, std::optional<Capabilities> declared,
                 std::string declared_note)
      : argv_(std::move(argv)), options_(options),
        info_(detail::full_capabilities(std::move(name), command, -1)), caps_(declared) {
    info_.values = true; // whatever it writes of DRIVER.VALUES is read, unless it declares none
    info_.capabilities = std::move(declared_note);
    if (caps_)
      apply_capabilities(*caps_, info_);
    // A process that exits without reading its input must not kill us with SIGPIPE.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, nullptr);
  }

  [[nodiscard]] const DriverInfo& info() const override { return info_; }
  // Path scenes only to a driver that declares paths, and then only what a 2D library adapter
  // would take (one sample at the pixel centre, its coverage kinds, fill rules, curves, grid).
  // rule: SCENE.PRIM.PATH
  // rule: DRIVER.EXTERNAL.CAPABILITIES, DRIVER.EXTERNAL.PATHS
  [[nodiscard]] std::string unsupported(const Scene& scene) const override {
    const bool paths =
        std::any_of(scene.primitives.begin(), scene.primitives.end(),
                    [](const Primitive& p) { return p.type == PrimitiveType::kPath; });
    if (paths && !caps_)
      return "paths not declared by the driver (it answered no capabilities query)";
    if (caps_) {
      if (std::string why = undeclared(*caps_, scene); !why.empty())
        return why;
    }
    return paths ? detail::path_unsupported(info_.paths, info_.name, scene, /*paths_only=*/false)
                 : std::string();
  }

  [[nodiscard]] DrawResult draw(const Scene& scene) override {
    return detail::coverage_of(draw_values(scene));
  }

  // rule: DRIVER.EXTERNAL.PROTOCOL, DRIVER.VALUES
  [[nodiscard]] ValuesResult draw_values(const Scene& scene) override {
    const std::string& cmd = info_.description;
    const std::string input = io::write_scene(scene);
    DriverProcess process(argv_, input, options_);
    if (!process.spawn_error().empty())
      return DriverError{"external driver: " + process.spawn_error()};
    // The output is read as it comes, until its first error; the rest is read and dropped, so
    // that a crash, an exit status or a timeout is still reported before malformed output.
    auto parsed =
        read_external_drawing([&] { return process.next_output(); }, scene, options_.max_fragments);
    const ProcessResult r = process.finish();
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
    if (auto* e = std::get_if<std::string>(&parsed)) {
      return DriverError{"external driver \"" + cmd + "\": malformed output: " + *e};
    }
    return std::get<Drawing>(std::move(parsed));
  }

private:
  std::vector<std::string> argv_;
  ExternalOptions options_;
  DriverInfo info_;
  std::optional<Capabilities> caps_; // none: the driver declared nothing
};

// The capabilities query (DRIVER.EXTERNAL.CAPABILITIES): runs the command once with
// RASTRULES_QUERY=capabilities in its environment and nothing on its standard input. A reply
// {"capabilities": {...}} (exit status 0) is parsed strictly; anything else declares nothing.
// Returns the capabilities (or nullopt) and a note for reports, or an error for a malformed
// reply.
struct QueryResult {
  std::optional<Capabilities> caps;
  std::string note;
  std::string error;
  std::string err; // the first bytes of the query's standard error, one line
};

// rule: DRIVER.EXTERNAL.CAPABILITIES
QueryResult query_capabilities(const std::vector<std::string>& argv, ExternalOptions options) {
  static const std::string env =
      std::string(kCapabilitiesQueryVariable) + "=" + kCapabilitiesQueryValue;
  options.max_output_bytes = std::min<std::size_t>(options.max_output_bytes, 1 << 16);
  DriverProcess process(argv, std::string(), options, env.c_str());
  if (!process.spawn_error().empty())
    return {std::nullopt, "none declared (" + process.spawn_error() + ")", {}, {}};
  std::string out;
  for (std::string_view piece = process.next_output(); !piece.empty();
       piece = process.next_output())
    out += piece;
  const ProcessResult r = process.finish();
  const std::string err = one_line(r.err);
  if (r.timed_out || r.output_overflow || r.signal != 0 || !r.exited || r.exit_status != 0)
    return {std::nullopt, "none declared (the query did not exit with status 0)", {}, err};
  const std::size_t first = out.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || out.compare(first, 15, "{\"capabilities\"") != 0)
    return {std::nullopt, "none declared (no {\"capabilities\": ...} reply)", {}, err};
  auto parsed = parse_capabilities(out);
  if (auto* e = std::get_if<std::string>(&parsed))
    return {std::nullopt, {}, std::move(*e), err};
  return {std::get<Capabilities>(parsed), "declared", {}, err};
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

// The keys of a fragment (DRIVER.EXTERNAL.PROTOCOL, SCENE.OUTPUT.MSAA).
// kPart to kPassed are the pipeline fragment's (SCENE.OUTPUT.PIPELINE, DRIVER.VALUES); kAlpha an
// antialiased path's (DRIVER.EXTERNAL.PATHS).
enum FragmentKey : unsigned {
  kPrim,
  kX,
  kY,
  kMask,
  kSeg,
  kSample,
  kHelper,
  kCoverage,
  kCentroid,
  kDdx,
  kDdy,
  kPart,
  kBary,
  kAttr,
  kDepth,
  kPassed,
  kAlpha,
  kKeyCount
};
constexpr std::array<std::string_view, kKeyCount> kKeyNames = {
    "prim", "x",   "y",    "mask", "seg",  "sample", "helper", "coverage", "centroid",
    "ddx",  "ddy", "part", "bary", "attr", "depth",  "passed", "alpha"};

// The fragments read so far, each (prim, x, y, seg, sample) once: an open-addressing hash set
// of indices into the list (4 bytes a slot, at most half the slots used), so that a repeat is
// found when it is read.
class FragmentSet {
public:
  // Adds frags.back() (of part parts.back(); parts may be empty: no parts) unless an earlier
  // fragment has its key; returns whether it was added.
  bool add_last(const std::vector<Fragment>& frags, const std::vector<std::uint32_t>& parts) {
    parts_ = &parts;
    if (2 * (frags.size() + 1) > slots_.size())
      grow(frags);
    const auto index = static_cast<std::uint32_t>(frags.size() - 1);
    for (std::size_t s = hash(frags.back()) & (slots_.size() - 1);;
         s = (s + 1) & (slots_.size() - 1)) {
      if (slots_[s] == 0) {
        slots_[s] = index + 1;
        return true;
      }
      if (same(frags[slots_[s] - 1], frags.back()) && part(slots_[s] - 1) == part(index))
        return false;
    }
  }

private:
  static std::uint64_t key_of(const Fragment& f) {
    return (std::uint64_t{f.prim} << 32) ^ (std::uint64_t{static_cast<std::uint32_t>(f.y)} << 16) ^
           static_cast<std::uint32_t>(f.x);
  }
  static std::size_t hash(const Fragment& f) {
    std::uint64_t h = key_of(f) ^
                      (std::uint64_t{f.seg.value_or(0xffffffffu)} * 0x9e3779b97f4a7c15u) ^
                      (std::uint64_t{f.sample.value_or(0xffffffffu)} << 40);
    h ^= h >> 31; // splitmix64's finalizer
    h *= 0xbf58476d1ce4e5b9u;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebu;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
  static bool same(const Fragment& a, const Fragment& b) {
    return a.prim == b.prim && a.x == b.x && a.y == b.y && a.seg == b.seg && a.sample == b.sample;
  }
  void grow(const std::vector<Fragment>& frags) {
    slots_.assign(std::max<std::size_t>(64, 2 * slots_.size()), 0);
    for (std::size_t i = 0; i + 1 < frags.size(); ++i) {
      std::size_t s = hash(frags[i]) & (slots_.size() - 1);
      while (slots_[s] != 0)
        s = (s + 1) & (slots_.size() - 1);
      slots_[s] = static_cast<std::uint32_t>(i + 1);
    }
  }

  [[nodiscard]] std::uint32_t part(std::size_t i) const {
    return parts_->empty() ? 0u : (*parts_)[i];
  }

  std::vector<std::uint32_t> slots_; // 0: empty; else the fragment's index + 1
  const std::vector<std::uint32_t>* parts_ = nullptr;
};

// The protocol's reader: a strict streaming handler (io::JsonHandler, as the scene reader's)
// that checks each value when it is read, keeps only the fragments, and stops at the first
// error. The schema bounds nesting to 4 levels ({"fragments": [{"centroid": [x, y]}]}): a value
// of the wrong type is an error at its first character.
// rule: DRIVER.EXTERNAL.PROTOCOL
class FragmentReader final : public io::JsonHandler {
public:
  FragmentReader(const Scene& scene, std::uint64_t max_fragments)
      : scene_(scene), samples_(scene.msaa.count()), max_fragments_(max_fragments) {
    if (scene.depth && scene.conventions.depth != pipe::DepthFormat::kD32F)
      depth_max_ = scene.conventions.depth == pipe::DepthFormat::kD16 ? 65535u : 16777215u;
  }

  bool value(const io::JsonValue& v) override {
    switch (at_) {
    case At::kStart:
      if (v.kind != io::JsonKind::kObject)
        return fail(kExpected);
      at_ = At::kRoot;
      return true;
    case At::kRoot: // the value of "fragments"
      if (v.kind != io::JsonKind::kArray)
        return fail(kExpected);
      at_ = At::kList;
      return true;
    case At::kList:
      if (frags_.size() >= max_fragments_) {
        return fail("fragments: more than " + std::to_string(max_fragments_) +
                    " fragments (limit DRIVER.EXTERNAL.PROTOCOL)");
      }
      path_ = "fragments[" + std::to_string(frags_.size()) + "]";
      if (v.kind != io::JsonKind::kObject)
        return fail(path_ + ": must be an object");
      at_ = At::kFragment;
      seen_ = 0;
      frag_ = Fragment{};
      vals_ = driver::FragmentValues{};
      passed_ = 0;
      return true;
    case At::kFragment:
      return fragment_value(v);
    case At::kBary: // an element of "bary": accepted, not compared
      if (v.kind != io::JsonKind::kInt || ++pair_count_ > 4)
        return fail(field() + ": must be [e0, e1, e2, A], four integers");
      return true;
    case At::kAttr: // the value of attribute attr_index_
      return attr_value(v);
    case At::kDepth:
      return depth_value(v);
    case At::kPair: // an element of "centroid", "ddx" or "ddy"
      if (!is_number(v) || ++pair_count_ > 2)
        return fail(field() + ": must be [x, y], two numbers");
      return true;
    case At::kDone:
      break;
    }
    return fail(kExpected);
  }

  bool key(std::string_view k) override {
    if (at_ == At::kAttr) {
      // rule: DRIVER.VALUES
      const auto& decl = scene_.attributes;
      const auto it = std::find_if(decl.begin(), decl.end(),
                                   [&](const pipe::AttributeDecl& a) { return a.name == k; });
      if (it == decl.end()) {
        return fail(field() + "." + io::printable(k, 40) + ": not an attribute the scene declares");
      }
      attr_index_ = static_cast<std::size_t>(it - decl.begin());
      if ((attr_seen_ >> attr_index_ & 1u) != 0)
        return fail(twice(k));
      attr_seen_ |= 1u << attr_index_;
      return true;
    }
    if (at_ == At::kRoot) {
      if (k != "fragments")
        return fail(io::printable(k, 40) + ": unknown key (expected fragments)");
      if (fragments_seen_)
        return fail(twice(k));
      fragments_seen_ = true;
      return true;
    }
    const auto* known = std::find(kKeyNames.begin(), kKeyNames.end(), k);
    if (known == kKeyNames.end())
      return fail(path_ + "." + io::printable(k, 40) + ": unknown key");
    key_ = static_cast<FragmentKey>(known - kKeyNames.begin());
    if ((seen_ & (1u << key_)) != 0)
      return fail(twice(k));
    seen_ |= 1u << key_;
    return true;
  }

  bool end_array() override {
    if (at_ == At::kPair) {
      if (pair_count_ != 2)
        return fail(field() + ": must be [x, y], two numbers");
      at_ = At::kFragment;
      return true;
    }
    if (at_ == At::kBary) {
      if (pair_count_ != 4)
        return fail(field() + ": must be [e0, e1, e2, A], four integers");
      at_ = At::kFragment;
      return true;
    }
    if (at_ == At::kDepth) {
      at_ = At::kFragment;
      return true;
    }
    at_ = At::kRoot; // the end of "fragments"
    return true;
  }

  bool end_object() override {
    if (at_ == At::kAttr) {
      // rule: DRIVER.VALUES
      for (std::size_t a = 0; a < scene_.attributes.size(); ++a) {
        if ((attr_seen_ >> a & 1u) == 0)
          return fail(field() + "." + io::printable(scene_.attributes[a].name, 40) + ": missing");
      }
      at_ = At::kFragment;
      return true;
    }
    if (at_ == At::kRoot) {
      if (!fragments_seen_)
        return fail(kExpected);
      at_ = At::kDone;
      return true;
    }
    for (const FragmentKey k : {kPrim, kX, kY}) {
      if ((seen_ & (1u << k)) == 0)
        return fail(path_ + "." + std::string(kKeyNames[k]) + ": missing");
    }
    // rule: DRIVER.VALUES
    if ((seen_ & (1u << kDepth)) != 0 &&
        vals_.depth.size() != static_cast<std::size_t>(std::popcount(frag_.mask))) {
      return fail(path_ + ".depth: " + std::to_string(vals_.depth.size()) + " value(s) for the " +
                  std::to_string(std::popcount(frag_.mask)) + " sample(s) of mask " +
                  std::to_string(frag_.mask) + " (one per covered sample)");
    }
    if ((passed_ & ~frag_.mask) != 0) {
      return fail(path_ + ".passed: " + std::to_string(passed_) + " has samples outside mask " +
                  std::to_string(frag_.mask));
    }
    // rule: DRIVER.EXTERNAL.PATHS
    const Primitive& prim = scene_.primitives[frag_.prim];
    const bool area = prim.path && prim.path->coverage == path::Coverage::kArea;
    const bool alpha = (seen_ & (1u << kAlpha)) != 0;
    if (area != alpha) {
      return fail(path_ + ".alpha: " +
                  (area ? "missing (primitive " + std::to_string(frag_.prim) +
                              " is a path with coverage \"area\")"
                        : "primitive " + std::to_string(frag_.prim) +
                              " is not a path with coverage \"area\""));
    }
    if (area)
      frag_.area = detail::alpha_area(alpha_);
    frags_.push_back(frag_);
    if (vals_.part && !with_parts_) {
      with_parts_ = true;
      parts_.assign(frags_.size() - 1, 0u);
    }
    if (with_parts_)
      parts_.push_back(vals_.part ? *vals_.part + 1 : 0u);
    if ((!vals_.attr.empty() || !vals_.depth.empty() || vals_.part) && !with_values_) {
      with_values_ = true;
      values_.resize(frags_.size() - 1);
    }
    if (with_values_)
      values_.push_back(std::move(vals_));
    if (!set_.add_last(frags_, parts_)) {
      return fail(path_ + ": duplicate fragment (prim " + std::to_string(frag_.prim) + ", x " +
                  std::to_string(frag_.x) + ", y " + std::to_string(frag_.y) + ")");
    }
    at_ = At::kList;
    return true;
  }

  bool syntax_error(const io::JsonSyntaxError& e) override {
    // 406: a number beyond every number type the JSON library has.
    return fail((e.id == 406 ? "not JSON the protocol allows: " : "not JSON: ") + e.what);
  }

  // The fragments (and values) sorted as SCENE.OUTPUT.FRAGMENTS, or the first error.
  std::variant<driver::Drawing, std::string> result(const io::JsonParseEnd& end) {
    if (!error_.empty())
      return error_;
    if (end.nul)
      return "not JSON: " + *end.nul;
    if (!end.ok)
      return std::string("not JSON: the output ended early");
    driver::Drawing d{std::move(frags_), std::move(values_)};
    sort_drawing(d);
    return d;
  }

private:
  enum class At { kStart, kRoot, kList, kFragment, kPair, kBary, kAttr, kDepth, kDone };
  static constexpr const char* kExpected = "expected {\"fragments\": [...]}";

  static bool is_number(const io::JsonValue& v) {
    return v.kind == io::JsonKind::kInt || v.kind == io::JsonKind::kUint ||
           v.kind == io::JsonKind::kFloat;
  }
  static std::string twice(std::string_view k) {
    return "the key \"" + io::printable(k, 40) + "\" is given twice in one object";
  }
  std::string field() const { return path_ + "." + std::string(kKeyNames[key_]); }

  bool fail(std::string message) {
    if (error_.empty())
      error_ = std::move(message);
    return false;
  }

  // One value of a fragment's key, checked against the scene.
  bool fragment_value(const io::JsonValue& v) {
    const bool integer = v.kind == io::JsonKind::kInt;
    const std::int64_t i = v.i;
    switch (key_) {
    case kPrim:
      if (!integer)
        return fail(field() + ": must be an integer");
      if (i < 0 || i >= static_cast<std::int64_t>(scene_.primitives.size())) {
        return fail(field() + ": " + std::to_string(i) + " is not a primitive of the scene (" +
                    std::to_string(scene_.primitives.size()) + " primitives)");
      }
      frag_.prim = static_cast<std::uint32_t>(i);
      return true;
    case kX:
    case kY: {
      if (!integer)
        return fail(field() + ": must be an integer");
      const bool is_x = key_ == kX;
      const std::int32_t size = is_x ? scene_.width : scene_.height;
      if (i < 0 || i >= size) {
        return fail(field() + ": " + std::to_string(i) + " is outside the target (" +
                    (is_x ? "width " : "height ") + std::to_string(size) + ")");
      }
      (is_x ? frag_.x : frag_.y) = static_cast<std::int32_t>(i);
      return true;
    }
    case kMask:
      if (!integer)
        return fail(field() + ": must be an integer");
      if (i < 0 || i > static_cast<std::int64_t>(full_mask(samples_))) {
        return fail(field() + ": " + std::to_string(i) + " has bits beyond the " +
                    std::to_string(samples_) + " sample(s) of the scene");
      }
      frag_.mask = static_cast<std::uint32_t>(i);
      return true;
    case kSeg:
      if (!integer || i < 0 || i > UINT32_MAX)
        return fail(field() + ": must be a non-negative integer");
      frag_.seg = static_cast<std::uint32_t>(i);
      return true;
    case kSample:
      if (!integer || i < 0 || i >= samples_)
        return fail(field() + ": must be a sample index below " + std::to_string(samples_));
      frag_.sample = static_cast<std::uint32_t>(i);
      return true;
    case kHelper:
      if (v.kind != io::JsonKind::kBool)
        return fail(field() + ": must be true or false");
      frag_.helper = v.b;
      return true;
    case kCoverage: // accepted, not compared
      if (!is_number(v))
        return fail(field() + ": must be a number");
      return true;
    case kCentroid: // accepted, not compared
    case kDdx:
    case kDdy:
      if (v.kind != io::JsonKind::kArray)
        return fail(field() + ": must be [x, y], two numbers");
      at_ = At::kPair;
      pair_count_ = 0;
      return true;
    // rule: DRIVER.VALUES
    case kPart:
      if (!integer || i < 0 || i > UINT32_MAX)
        return fail(field() + ": must be a non-negative integer");
      vals_.part = static_cast<std::uint32_t>(i);
      return true;
    case kBary: // accepted, not compared
      if (v.kind != io::JsonKind::kArray)
        return fail(field() + ": must be [e0, e1, e2, A], four integers");
      at_ = At::kBary;
      pair_count_ = 0;
      return true;
    case kAttr:
      if (scene_.attributes.empty())
        return fail(field() + ": the scene declares no attributes");
      if (v.kind != io::JsonKind::kObject)
        return fail(field() + ": must be an object {\"name\": value, ...}");
      at_ = At::kAttr;
      attr_seen_ = 0;
      vals_.attr.assign(scene_.attributes.size(), 0.0f);
      return true;
    case kDepth:
      if (!scene_.depth)
        return fail(field() + ": the scene has no depth");
      if (v.kind != io::JsonKind::kArray)
        return fail(field() + ": must be an array, one stored depth per covered sample");
      at_ = At::kDepth;
      return true;
    // rule: DRIVER.EXTERNAL.PATHS
    case kAlpha:
      if (!integer || i < 1 || i > 255)
        return fail(field() + ": must be an integer in [1, 255] (8-bit alpha; 0 is no fragment)");
      alpha_ = static_cast<std::uint8_t>(i);
      return true;
    case kPassed:
      if (!scene_.depth)
        return fail(field() + ": the scene has no depth");
      if (!integer || i < 0 || i > static_cast<std::int64_t>(full_mask(samples_))) {
        return fail(field() + ": must be a sample mask of the scene's " + std::to_string(samples_) +
                    " sample(s)");
      }
      passed_ = static_cast<std::uint32_t>(i);
      return true;
    case kKeyCount:
      break;
    }
    return fail(field() + ": unknown key");
  }

  // rule: DRIVER.VALUES
  bool attr_value(const io::JsonValue& v) {
    const std::optional<float> f = io::json_float32(v);
    if (!f) {
      return fail(field() + "." + io::printable(scene_.attributes[attr_index_].name, 40) +
                  ": must be a number (or \"NaN\", \"Infinity\", \"-Infinity\")");
    }
    vals_.attr[attr_index_] = *f;
    return true;
  }

  // rule: DRIVER.VALUES
  bool depth_value(const io::JsonValue& v) {
    const std::string at = field() + "[" + std::to_string(vals_.depth.size()) + "]";
    if (vals_.depth.size() >= samples_)
      return fail(field() + ": more values than the scene's " + std::to_string(samples_) +
                  " sample(s)");
    pipe::DepthValue d;
    if (depth_max_ != 0) {
      if (v.kind != io::JsonKind::kInt || v.i < 0 || v.i > depth_max_) {
        return fail(at + ": must be an integer in [0, " + std::to_string(depth_max_) + "] (" +
                    std::string(io::depth_format_name(scene_.conventions.depth)) + ")");
      }
      d.unorm = static_cast<std::uint32_t>(v.i);
    } else {
      const std::optional<float> f = io::json_float32(v);
      if (!f)
        return fail(at + ": must be a number (d32f)");
      d.f = *f;
    }
    vals_.depth.push_back(d);
    return true;
  }

  const Scene& scene_;
  const std::uint32_t samples_;
  std::int64_t depth_max_ = 0; // d16 and d24: the largest stored value; 0: d32f or no depth
  const std::uint64_t max_fragments_;
  At at_ = At::kStart;
  bool fragments_seen_ = false;
  std::string path_; // "fragments[i]" of the fragment being read
  FragmentKey key_ = kPrim;
  unsigned seen_ = 0; // keys of this fragment given so far (bit k: kKeyNames[k])
  Fragment frag_;
  int pair_count_ = 0;
  std::vector<Fragment> frags_;
  // DRIVER.VALUES: the current fragment's values and passed mask, the attributes it has given;
  // per fragment read, its part + 1 (0: none) and its values, both empty until the first
  // fragment that has them.
  driver::FragmentValues vals_;
  std::uint32_t passed_ = 0;
  std::uint8_t alpha_ = 0; // DRIVER.EXTERNAL.PATHS: the current fragment's "alpha"
  std::uint32_t attr_seen_ = 0;
  std::size_t attr_index_ = 0;
  bool with_parts_ = false, with_values_ = false;
  std::vector<std::uint32_t> parts_;
  std::vector<driver::FragmentValues> values_;
  FragmentSet set_;
  std::string error_;
};

} // namespace

namespace {
std::variant<std::vector<Fragment>, std::string>
fragments_of(std::variant<Drawing, std::string> r) {
  if (auto* e = std::get_if<std::string>(&r))
    return std::move(*e);
  return std::move(std::get<Drawing>(r).fragments);
}
} // namespace

// rule: DRIVER.EXTERNAL.PROTOCOL, DRIVER.VALUES
std::variant<Drawing, std::string> parse_external_drawing(std::string_view text, const Scene& scene,
                                                          std::uint64_t max_fragments) {
  FragmentReader reader(scene, max_fragments);
  return reader.result(io::parse_json(text, reader));
}

// rule: DRIVER.EXTERNAL.PROTOCOL, DRIVER.VALUES
std::variant<Drawing, std::string>
read_external_drawing(const std::function<std::string_view()>& next, const Scene& scene,
                      std::uint64_t max_fragments) {
  FragmentReader reader(scene, max_fragments);
  return reader.result(io::parse_json(next, reader));
}

// rule: DRIVER.EXTERNAL.PROTOCOL
std::variant<std::vector<Fragment>, std::string>
parse_external_fragments(std::string_view text, const Scene& scene, std::uint64_t max_fragments) {
  return fragments_of(parse_external_drawing(text, scene, max_fragments));
}

// rule: DRIVER.EXTERNAL.PROTOCOL
std::variant<std::vector<Fragment>, std::string>
read_external_fragments(const std::function<std::string_view()>& next, const Scene& scene,
                        std::uint64_t max_fragments) {
  return fragments_of(read_external_drawing(next, scene, max_fragments));
}

std::unique_ptr<Driver> open_external_driver(std::string_view command, std::string* error,
                                             ExternalOptions options) {
  if (external_argv(command).empty()) {
    if (error != nullptr)
      *error = "external driver: empty command (use external:COMMAND)";
    return nullptr;
  }
  QueryResult q = query_capabilities(external_argv(command), options);
  if (!q.error.empty()) {
    if (error != nullptr)
      *error = "external driver \"" + std::string(command) + "\": " + q.error;
    return nullptr;
  }
  return std::make_unique<ExternalDriver>("external", external_argv(command), std::string(command),
                                          options, q.caps, std::move(q.note));
}

// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
std::string node_drivers_dir() {
  if (const char* dir = std::getenv(kNodeDriversVariable); dir != nullptr && *dir != '\0')
    return dir;
#if defined(RASTRULES_NODE_DRIVERS_DIR)
  return RASTRULES_NODE_DRIVERS_DIR;
#else
  return "tools/driver/node";
#endif
}

namespace {

// Whether an executable named `name` is found on PATH, as posix_spawnp would look for it.
bool on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string_view rest = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
  while (true) {
    const std::size_t colon = rest.find(':');
    const std::string dir(rest.substr(0, colon));
    if (::access(((dir.empty() ? "." : dir) + "/" + name).c_str(), X_OK) == 0)
      return true;
    if (colon == std::string_view::npos)
      return false;
    rest.remove_prefix(colon + 1);
  }
}

// Opens a driver that is a Node program of node_drivers_dir() run through the protocol: `name`
// is the driver's name, `script` its program, `package` the npm package it loads. Opening fails
// with one line saying what to run when node, the program or the package is missing, and when the
// program answers no capabilities (it would otherwise be assumed to draw everything).
// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA, DRIVER.EXTERNAL.PATHS
std::unique_ptr<Driver> open_node_driver(std::string_view arg, std::string* error,
                                         const std::string& name, const std::string& script,
                                         const std::string& package) {
  std::string ignored;
  std::string& err = error != nullptr ? *error : ignored;
  if (!arg.empty()) {
    err = "driver '" + name + "' takes no argument";
    return nullptr;
  }
  ExternalOptions options = default_external_options(&err);
  if (!err.empty())
    return nullptr;
  const std::string dir = node_drivers_dir();
  const std::string program = dir + "/" + script;
  const std::string install = "run scripts/deps (or: npm ci --prefix " + dir + ")";
  if (!on_path("node")) {
    err = name + ": node is not installed (no \"node\" on PATH); " + install;
    return nullptr;
  }
  if (::access(program.c_str(), R_OK) != 0) {
    err = name + ": " + program + " not found (" + kNodeDriversVariable +
          " names the directory of the Node drivers)";
    return nullptr;
  }
  if (::access((dir + "/node_modules/" + package + "/package.json").c_str(), R_OK) != 0) {
    err = name + ": the npm package " + package + " is not installed in " + dir +
          "/node_modules; " + install;
    return nullptr;
  }
  std::vector<std::string> argv = {"node", program};
  const std::string command = "node " + program;
  QueryResult q = query_capabilities(argv, options);
  if (!q.error.empty() || !q.caps) {
    err = name + " (" + command +
          "): " + (!q.error.empty() ? q.error : "no capabilities: " + q.note) +
          (q.err.empty() ? "" : "; its standard error: " + q.err);
    return nullptr;
  }
  return std::make_unique<ExternalDriver>(name, std::move(argv), command, options, q.caps,
                                          std::move(q.note));
}

} // namespace

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

// rule: DRIVER.PATH.SKIA
std::unique_ptr<Driver> open_skia(std::string_view arg, std::string* error) {
  return open_node_driver(arg, error, "skia", "skia.mjs", "canvaskit-wasm");
}

// rule: DRIVER.PATH.TINY_SKIA
std::unique_ptr<Driver> open_tiny_skia(std::string_view arg, std::string* error) {
  return open_node_driver(arg, error, "tiny-skia", "tiny-skia.mjs", "@resvg/resvg-js");
}
} // namespace detail

} // namespace rastrules::driver
