// SPDX-License-Identifier: MIT
// libFuzzer target: the arguments of `rastrules render` and `rastrules explain` (path names,
// output options, their values, their order and repetitions), run in-process on small fixed
// scenes in a scratch folder. Must never crash, leak or hit undefined behaviour, and
// - the exit status is 0, 1 (explain: the pixel is not covered) or 2 (bad input);
// - a failed command prints exactly one "rastrules: error:" line, first (a usage error adds
//   one hint line "run 'rastrules COMMAND --help'" after it, never the help) and a successful
//   one none; --help prints the command's help and succeeds; no exception escapes (the command
//   line's main would report it as an internal error);
// - a failed command leaves the folder as it was: no output file, no input overwritten;
// - no temporary output file (.rastrules-PID-N.tmp) is ever left behind (an output the
//   command names may itself begin with ".rastrules-": only the temporaries' form counts).
// The input is the command (first byte: even render, odd explain) and up to 12 arguments
// separated by '\n'. An argument holding '/' is skipped, so every output stays in the scratch
// folder (the fuzzer may run as root).
// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS

#include <fcntl.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;

// The inputs every run finds in its folder: a multisampled scene with a line strip, a
// pipeline scene, and a bad one.
const std::map<std::string, std::string> kInputs = {
    {"s.json", R"({"target": {"width": 8, "height": 6}, "samples": 4, "centroid": "d3d11",
 "primitives": [{"type": "triangle", "v": [[0, 0], [8, 0], [0, 6]]},
  {"type": "line_strip", "v": [[0.5, 5.5], [7.5, 0.5], [7.5, 5.5]]},
  {"type": "point", "v": [[3.5, 2.5]]}]})"},
    {"p.json", R"({"target": {"width": 8, "height": 8},
 "depth": {"format": "d24", "func": "less"}, "attributes": [{"name": "u"}],
 "primitives": [{"type": "triangle", "pos": [[-1, -1, 0.5, 1], [3, -1, 0.5, 2], [-1, 3, 0.5, 1]],
   "attr": [[0], [1], [2]]}]})"},
    {"bad.json", R"({"target": {"width": 0, "height": 4}, "primitives": []})"},
};

struct Sandbox {
  fs::path root; // holds work/ (the current folder) and the captured standard error
  fs::path work;
  fs::path err;
};

const Sandbox& sandbox() {
  static const Sandbox box = [] {
    Sandbox b;
    char tmpl[] = "/tmp/rastrules-fuzz-cli-XXXXXX";
    const char* made = ::mkdtemp(tmpl);
    if (made == nullptr)
      std::abort();
    b.root = made;
    b.work = b.root / "work";
    b.err = b.root / "stderr";
    fs::create_directories(b.work);
    return b;
  }();
  return box;
}

// Empties the folder and writes the inputs afresh.
void reset(const Sandbox& box) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(box.work, ec))
    fs::remove_all(e.path(), ec);
  for (const auto& [name, text] : kInputs)
    std::ofstream(box.work / name, std::ios::binary) << text;
}

// True for the form of io::OutputFile's temporaries: ".rastrules-" digits "-" digits ".tmp".
bool is_temporary_name(const std::string& name) {
  const std::string head = ".rastrules-", tail = ".tmp";
  if (name.size() < head.size() + tail.size() + 3 || name.rfind(head, 0) != 0 ||
      name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return false;
  const std::string mid = name.substr(head.size(), name.size() - head.size() - tail.size());
  const std::size_t dash = mid.find('-');
  const auto digits = [](const std::string& s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
  };
  return dash != std::string::npos && digits(mid.substr(0, dash)) && digits(mid.substr(dash + 1));
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Runs the command in the scratch folder with standard output discarded and standard error
// captured (the current folder is restored after: libFuzzer reads its inputs by relative path).
int run(bool render, const std::vector<std::string>& args, std::string& err) {
  const Sandbox& box = sandbox();
  const fs::path back = fs::current_path();
  fs::current_path(box.work);
  std::fflush(stdout);
  std::fflush(stderr);
  const int saved_out = ::dup(1), saved_err = ::dup(2);
  const int null_fd = ::open("/dev/null", O_WRONLY);
  const int err_fd = ::open(box.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ::dup2(null_fd, 1);
  ::dup2(err_fd, 2);
  int status = -1;
  // Each input starts from the default verbosity (an earlier input's -q/-v must not leak).
  rastrules::cli::set_verbosity(rastrules::cli::Verbosity::kNormal);
  try {
    status = render ? rastrules::cli::run_render(args) : rastrules::cli::run_explain(args);
  } catch (const std::bad_alloc&) {
    status = -2;
  } catch (const std::exception&) {
    status = -3;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  ::dup2(saved_out, 1);
  ::dup2(saved_err, 2);
  for (const int fd : {saved_out, saved_err, null_fd, err_fd})
    ::close(fd);
  fs::current_path(back);
  err = read(box.err);
  return status;
}

[[noreturn]] void fail(const std::string& what, const std::vector<std::string>& details,
                       const std::uint8_t* data, std::size_t size) {
  rastrules::fuzz::fail(what, details, nullptr, data, size);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > 2048)
    return 0;
  const bool render = (data[0] & 1u) == 0;
  std::vector<std::string> args;
  std::string cur;
  for (std::size_t i = 1; i <= size; ++i) {
    if (i == size || data[i] == '\n') {
      if (cur.find('/') == std::string::npos && cur.size() <= 300)
        args.push_back(cur);
      cur.clear();
      if (args.size() == 12)
        break;
    } else {
      cur += static_cast<char>(data[i]);
    }
  }
  const Sandbox& box = sandbox();
  reset(box);
  std::string err;
  const int status = run(render, args, err);

  std::vector<std::string> details;
  std::string shown = "rastrules " + std::string(render ? "render" : "explain");
  for (const std::string& a : args)
    shown += " '" + a + "'";
  details.push_back(shown);
  details.push_back("stderr: " + err.substr(0, 2000));
  if (status != 0 && status != 1 && status != 2)
    fail("exit status " + std::to_string(status) + " (-2: out of memory, -3: an exception)",
         details, data, size);
  // Lines that begin with the error prefix (an argument echoed inside the line may hold it).
  std::size_t error_lines = 0;
  for (std::size_t at = 0; at < err.size(); at = err.find('\n', at) + 1) {
    if (err.compare(at, 17, "rastrules: error:") == 0)
      ++error_lines;
    if (err.find('\n', at) == std::string::npos)
      break;
  }
  if (status == 2 && (error_lines != 1 || err.rfind("rastrules: error: ", 0) != 0))
    fail("a failed command must print exactly one error line, first", details, data, size);
  // rule: SCENE.INPUT.ERRORS
  // At most the error line and one hint line: never the help after an error.
  std::size_t lines = 0;
  for (const char c : err)
    lines += c == '\n' ? 1u : 0u;
  if (status == 2 && lines > 2)
    fail("a usage error printed more than the error line and one hint", details, data, size);
  if (status == 0 && error_lines != 0)
    fail("a successful command printed an error", details, data, size);

  // The folder after the run: no temporary ever; after a failure, exactly the inputs.
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(box.work, ec)) {
    const std::string name = e.path().filename().string();
    if (is_temporary_name(name))
      fail("a temporary output file was left: " + name, details, data, size);
    if (status == 2 && kInputs.count(name) == 0)
      fail("a failed command left an output file: " + name, details, data, size);
  }
  if (status == 2) {
    for (const auto& [name, text] : kInputs) {
      if (read(box.work / name) != text)
        fail("a failed command changed the input " + name, details, data, size);
    }
  }
  return 0;
}
