// SPDX-License-Identifier: MIT
// The external-process driver: `rastrules render - --fragments -` is a conforming external
// driver, and every failure of an external process is a clear error.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>
#include <variant>

#include "rastrules/driver/driver.hpp"
#include "rastrules/driver/external.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::driver {
namespace {

class TempDir {
public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("rastrules-external-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  // Writes an executable shell script and returns its path.
  std::string script(const std::string& name, const std::string& body) const {
    const auto p = path_ / name;
    std::ofstream(p) << "#!/bin/sh\n" << body << "\n";
    ::chmod(p.c_str(), 0755);
    return p.string();
  }

private:
  std::filesystem::path path_;
};

Scene small_scene() {
  Scene s;
  s.width = 4;
  s.height = 4;
  s.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}}));
  return s;
}

std::string draw_error(const std::string& command, ExternalOptions options = {}) {
  std::string err;
  auto d = open_external_driver(command, &err, options);
  EXPECT_NE(d, nullptr) << err;
  if (!d)
    return err;
  auto r = d->draw(small_scene());
  if (auto* e = std::get_if<DriverError>(&r))
    return e->message;
  return "";
}

const std::string kRender = std::string(RASTRULES_CLI) + " render - --fragments -";

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriver, RastrulesRenderIsAConformingExternalDriver) {
  std::string err;
  auto d = open_driver("external:" + kRender, &err);
  ASSERT_NE(d, nullptr) << err;
  auto r = d->draw(small_scene());
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r)) << std::get<DriverError>(r).message;
  auto expected = render(small_scene());
  EXPECT_EQ(std::get<std::vector<Fragment>>(r), std::get<std::vector<Fragment>>(expected));
  // A short campaign over every family finds nothing.
  fuzzer::Settings s;
  s.driver_name = "external";
  s.cases = 25;
  s.seed = 11;
  const fuzzer::Summary sum = fuzzer::run_fuzz(*d, s);
  EXPECT_TRUE(sum.error.empty()) << sum.error;
  EXPECT_EQ(sum.cases, 25u);
  EXPECT_EQ(sum.mismatches, 0u);
}

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriver, CommandsAreSplitOrGivenToTheShell) {
  EXPECT_EQ(external_argv("/bin/prog  --a=1 x.json"),
            (std::vector<std::string>{"/bin/prog", "--a=1", "x.json"}));
  EXPECT_EQ(external_argv("prog 'a b'"), (std::vector<std::string>{"/bin/sh", "-c", "prog 'a b'"}));
  EXPECT_EQ(external_argv("a | b"), (std::vector<std::string>{"/bin/sh", "-c", "a | b"}));
  std::string err;
  EXPECT_EQ(open_driver("external:", &err), nullptr);
  EXPECT_NE(err.find("empty command"), std::string::npos) << err;
}

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriver, CrashNonZeroExitAndMissingProgramAreErrors) {
  TempDir dir;
  EXPECT_NE(
      draw_error(dir.script("crash.sh", "kill -SEGV $$")).find("crashed: killed by signal 11"),
      std::string::npos);
  const std::string exit3 = draw_error(dir.script("exit3.sh", "echo 'no such mode' >&2; exit 3"));
  EXPECT_NE(exit3.find("exited with status 3"), std::string::npos) << exit3;
  EXPECT_NE(exit3.find("no such mode"), std::string::npos) << exit3;
  EXPECT_NE(draw_error("/nonexistent/driver").find("cannot start"), std::string::npos);
}

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriver, AHangingProcessIsKilledAtTheTimeout) {
  TempDir dir;
  ExternalOptions o;
  o.timeout_ms = 200;
  const auto start = std::chrono::steady_clock::now();
  const std::string e = draw_error(dir.script("hang.sh", "sleep 30"), o);
  const auto elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_NE(e.find("timed out after 200 ms"), std::string::npos) << e;
  EXPECT_LT(elapsed, std::chrono::seconds(5));
}

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriver, TooMuchOutputIsAnError) {
  TempDir dir;
  ExternalOptions o;
  o.max_output_bytes = 1000;
  const std::string e = draw_error(dir.script("flood.sh", "yes '{}'"), o);
  EXPECT_NE(e.find("more than 1000 bytes"), std::string::npos) << e;
}

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriver, MalformedOutputIsAnErrorNamingTheFragmentAndField) {
  TempDir dir;
  const auto out = [&](const std::string& json) {
    static int n = 0;
    return draw_error(dir.script("out" + std::to_string(n++) + ".sh",
                                 "cat > /dev/null; cat <<'EOF'\n" + json + "\nEOF"));
  };
  EXPECT_NE(out("garbage").find("malformed output: not JSON"), std::string::npos);
  EXPECT_NE(out("[]").find("expected {\"fragments\": [...]}"), std::string::npos);
  EXPECT_NE(out(R"({"fragments": [{"prim": 0, "x": 4, "y": 0}]})")
                .find("fragments[0].x: 4 is outside the target"),
            std::string::npos);
  EXPECT_NE(
      out(R"({"fragments": [{"prim": 0, "x": 1, "y": -1}]})").find("fragments[0].y: -1 is outside"),
      std::string::npos);
  EXPECT_NE(out(R"({"fragments": [{"prim": 1, "x": 1, "y": 1}]})")
                .find("fragments[0].prim: 1 is not a primitive"),
            std::string::npos);
  EXPECT_NE(out(R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "mask": 2}]})")
                .find("fragments[0].mask: 2 has bits beyond the 1 sample"),
            std::string::npos);
  EXPECT_NE(out(R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "colour": 2}]})")
                .find("fragments[0].colour: unknown key"),
            std::string::npos);
  EXPECT_NE(out(R"({"fragments": [{"prim": 0, "x": 1.5, "y": 1}]})")
                .find("fragments[0].x: must be an integer"),
            std::string::npos);
  EXPECT_NE(out(R"({"fragments": [{"prim": 0, "x": 1, "y": 1}, {"prim": 0, "x": 1, "y": 1}]})")
                .find("fragments[1]: duplicate"),
            std::string::npos);
  // Unsorted but valid output is accepted and sorted.
  TempDir dir2;
  std::string err;
  auto d = open_external_driver(
      dir2.script("ok.sh", "cat > /dev/null; echo '{\"fragments\": [{\"prim\": 0, \"x\": 2, \"y\": "
                           "1}, {\"prim\": 0, \"x\": 0, \"y\": 0, \"mask\": 1}]}'"),
      &err);
  ASSERT_NE(d, nullptr);
  auto r = d->draw(small_scene());
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r)) << std::get<DriverError>(r).message;
  EXPECT_EQ(std::get<std::vector<Fragment>>(r), (std::vector<Fragment>{{0, 0, 0}, {0, 2, 1}}));
}

} // namespace
// Regressions found by fuzz_external_protocol (fuzz/corpus/fuzz_external_protocol/regression_*):
// a number too large for any JSON number type made the parser throw an exception that was not
// caught (the process aborted), and deep nesting risked the recursive parser's stack. The
// streaming reader reports the number where it is read, and an array or object where the
// protocol has none is an error at its first character.
// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, NumberOverflowIsAnErrorNotAnAbort) {
  const auto r =
      parse_external_fragments(R"({"fragments": [{"prim": 555551e955}]})", small_scene());
  ASSERT_TRUE(std::holds_alternative<std::string>(r));
  EXPECT_NE(std::get<std::string>(r).find("number overflow"), std::string::npos)
      << std::get<std::string>(r);
  const auto r2 = parse_external_fragments(
      R"({"fragments": [{"prim": 0, "x": 1e999, "y": 0, "mask": 1}]})", small_scene());
  EXPECT_TRUE(std::holds_alternative<std::string>(r2));
}

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, DeepNestingIsRefusedAtItsFirstBracket) {
  const auto error_of = [](const std::string& text) {
    const auto r = parse_external_fragments(text, small_scene());
    return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : std::string();
  };
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(error_of("{\"fragments\": " + deep + "}"), "fragments[0]: must be an object");
  EXPECT_EQ(error_of(R"({"fragments": [{"prim": 0, "x": 0, "y": 0, "centroid": )" + deep + "}]}"),
            "fragments[0].centroid: must be [x, y], two numbers");
  EXPECT_EQ(error_of("[" + deep + "]"), "expected {\"fragments\": [...]}");
  // Brackets inside strings are no nesting: the key is what is wrong.
  EXPECT_EQ(error_of(R"({"fragments": [], "note": "[[[[[[[[[[[["})"),
            "note: unknown key (expected fragments)");
}

// Issue 17 item 6, found 2026-11-25: a raw NUL byte ended a driver's output for the JSON
// library, so valid output followed by NUL and garbage was accepted. Now a parse error with
// the NUL's position.
// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, ARawNulByteIsNotTheEndOfTheOutput) {
  const std::string text = std::string(R"({"fragments": []})") + std::string(1, '\0') + "junk";
  const auto r = parse_external_fragments(text, small_scene());
  ASSERT_TRUE(std::holds_alternative<std::string>(r));
  EXPECT_NE(std::get<std::string>(r).find("line 1, column 18: a raw NUL byte"), std::string::npos)
      << std::get<std::string>(r);
}

// Issue 17 item 10, found 2026-11-25: RASTRULES_EXTERNAL_TIMEOUT_MS above about 9.2e12
// overflowed the clock (every draw then "timed out") and "abc", "0", "-5" silently fell back to
// 10 s. Now one error line naming the variable and its range, and the driver is not opened.
// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, TheTimeoutVariableIsAnIntegerInItsRangeOrAnError) {
  struct Restore {
    ~Restore() { ::unsetenv("RASTRULES_EXTERNAL_TIMEOUT_MS"); }
  } restore;
  for (const char* bad : {"abc", "0", "-5", "9300000000000", "86400001", "12ms", ""}) {
    ::setenv("RASTRULES_EXTERNAL_TIMEOUT_MS", bad, 1);
    std::string err;
    EXPECT_EQ(open_driver("external:/bin/true", &err), nullptr) << bad;
    EXPECT_NE(err.find("RASTRULES_EXTERNAL_TIMEOUT_MS needs an integer in [1, 86400000]"),
              std::string::npos)
        << bad << ": " << err;
  }
  ::setenv("RASTRULES_EXTERNAL_TIMEOUT_MS", "86400000", 1);
  std::string err;
  EXPECT_EQ(default_external_options(&err).timeout_ms, 86400000);
  EXPECT_TRUE(err.empty()) << err;
  EXPECT_NE(open_driver("external:/bin/true", &err), nullptr) << err;
}

// Issue 17 item 11, found 2026-11-25: duplicate and unknown keys in a driver's output were
// accepted, the last value winning ({"fragments": [...], "fragments": []} became no fragment).
// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, DuplicateAndUnknownKeysAreErrors) {
  const auto error_of = [](const std::string& text) {
    const auto r = parse_external_fragments(text, small_scene());
    return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : std::string();
  };
  const std::pair<const char*, const char*> bad[] = {
      {R"({"fragments": [{"prim": 0, "x": 0, "y": 0}], "fragments": []})",
       "\"fragments\" is given twice"},
      {R"({"fragments": [{"prim": 0, "x": 0, "x": 1, "y": 0}]})", "\"x\" is given twice"},
      {R"({"fragments": [], "fragment": []})", "fragment: unknown key"}};
  for (const auto& [text, want] : bad)
    EXPECT_NE(error_of(text).find(want), std::string::npos) << text << ": " << error_of(text);
  // The same key in two objects is no repeat.
  EXPECT_EQ(
      error_of(R"({"fragments": [{"prim": 0, "x": 0, "y": 0}, {"prim": 0, "x": 1, "y": 0}]})"), "");
}

// Issue 17 item 7, found 2026-11-25: a driver's output was parsed into a document tree before
// any check: 66 MB of `{}` entries took 2.3 GB and 37 s, after the per-scene timeout. It is now
// read by a strict streaming reader while the process runs, within the timeout, stopping at the
// first bad fragment and holding only the fragments, at most ExternalOptions::max_fragments of
// them (scaled down here to 3; the default is 2^26, and 64 MiB of output hold at most 2917776).
// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, OutputBeyondTheFragmentLimitIsRefusedNamingIt) {
  TempDir dir;
  ExternalOptions o;
  o.max_fragments = 3;
  const std::string three = R"({"prim": 0, "x": 0, "y": 0}, {"prim": 0, "x": 1, "y": 0}, )"
                            R"({"prim": 0, "x": 2, "y": 0})";
  const auto driver = [&](const std::string& name, const std::string& list) {
    return dir.script(name, "cat > /dev/null; echo '{\"fragments\": [" + list + "]}'");
  };
  EXPECT_EQ(draw_error(driver("three.sh", three), o), "");
  const std::string e =
      draw_error(driver("four.sh", three + R"(, {"prim": 0, "x": 3, "y": 0})"), o);
  EXPECT_NE(e.find("malformed output: fragments: more than 3 fragments (limit "
                   "DRIVER.EXTERNAL.PROTOCOL)"),
            std::string::npos)
      << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  // The byte limit still applies to the whole output, read or dropped.
  o.max_output_bytes = 50;
  EXPECT_NE(draw_error(driver("long.sh", three), o).find("wrote more than 50 bytes"),
            std::string::npos);
}

// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, OutputIsReadPieceByPieceUntilTheFirstBadFragment) {
  // An endless output: the reader asks for the pieces it needs and no more.
  int asked = 0;
  const auto endless = [&]() -> std::string_view {
    return ++asked == 1 ? std::string_view(R"({"fragments": [{"prim": 0, "x": 0, "y": 0}, {})")
                        : std::string_view(", {}");
  };
  const auto r = read_external_fragments(endless, small_scene());
  ASSERT_TRUE(std::holds_alternative<std::string>(r));
  EXPECT_EQ(std::get<std::string>(r), "fragments[1].prim: missing");
  EXPECT_LE(asked, 2);
  // Pieces of any size read as the whole text does, a NUL byte's line and column included.
  const std::string text = "{\"fragments\":\n [{\"prim\": 0, \"x\": 3, \"y\": 2, \"mask\": 1},\n"
                           "  {\"prim\": 0, \"x\": 1, \"y\": 2}]}\n  ";
  for (const std::string& t : {text, text + std::string(1, '\0') + "junk"}) {
    const auto whole = parse_external_fragments(t, small_scene());
    for (const std::size_t size :
         {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{1000}}) {
      std::size_t at = 0;
      const auto pieces = [&]() -> std::string_view {
        const std::string_view piece = std::string_view(t).substr(at, size);
        at += piece.size();
        return piece;
      };
      EXPECT_EQ(read_external_fragments(pieces, small_scene()), whole) << size;
    }
  }
  const auto nul = parse_external_fragments(text + std::string(1, '\0'), small_scene());
  ASSERT_TRUE(std::holds_alternative<std::string>(nul));
  EXPECT_NE(std::get<std::string>(nul).find("line 4, column 3: a raw NUL byte"), std::string::npos)
      << std::get<std::string>(nul);
}

// Issue 17 item 9, found 2026-11-25: a driver's background children outlived it after a
// normal exit (fuzz --cases 20 left 20 processes). Its process group is now ended once it has
// exited, before it is reaped.
// rule: DRIVER.EXTERNAL.PROTOCOL
TEST(ExternalDriverRegression, BackgroundChildrenEndWithTheDriver) {
  TempDir dir;
  const std::string group_file = dir.script("group", "") + ".id";
  const std::string cmd = dir.script(
      "bg.sh", "cat > /dev/null; echo $$ > " + group_file +
                   "; sleep 300 < /dev/null > /dev/null 2>&1 &\necho '{\"fragments\": []}'");
  EXPECT_EQ(draw_error(cmd), "");
  std::ifstream in(group_file);
  pid_t group = 0;
  ASSERT_TRUE(in >> group);
  // Nothing of the group is left (it may take the kernel a moment to deliver SIGKILL).
  bool gone = false;
  for (int i = 0; i < 200 && !gone; ++i) {
    gone = ::kill(-group, 0) != 0 && errno == ESRCH;
    if (!gone)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(gone) << "process group " << group << " still has members";
}

} // namespace rastrules::driver

namespace rastrules::driver {
namespace {

// rule: DRIVER.EXTERNAL.CAPABILITIES
TEST(ExternalCapabilities, AReplyIsReadStrictlyAndAbsentKeysAllowEverything) {
  const auto all = parse_capabilities(R"({"capabilities": {}})");
  ASSERT_TRUE(std::holds_alternative<Capabilities>(all)) << std::get<std::string>(all);
  Scene s = small_scene();
  EXPECT_EQ(undeclared(std::get<Capabilities>(all), s), "");
  const auto some = parse_capabilities(
      R"({"capabilities": {"primitives": ["triangle"], "sample_counts": [1],
          "fill_conventions": ["top-left"], "sample_patterns": ["standard"], "pipeline": false,
          "sample_mask": false, "sample_shading": false, "antialiased_lines": false,
          "line_modes": ["d3d"], "max_target_side": 16, "subpixel_bits": 8}})");
  ASSERT_TRUE(std::holds_alternative<Capabilities>(some)) << std::get<std::string>(some);
  const Capabilities& c = std::get<Capabilities>(some);
  EXPECT_EQ(undeclared(c, s), "");
  Scene wide = s;
  wide.width = 17;
  EXPECT_NE(undeclared(c, wide).find("larger than its max_target_side 16"), std::string::npos);
  Scene ms = s;
  set_sample_pattern(ms, standard_pattern(4));
  EXPECT_EQ(undeclared(c, ms), "4 samples not declared by the driver");
  Scene line = s;
  Primitive seg;
  seg.type = PrimitiveType::kLine;
  seg.v = {FloatPoint{0, 0}, FloatPoint{3, 1}};
  line.primitives.push_back(seg);
  EXPECT_EQ(undeclared(c, line), "primitive type 'line' not declared by the driver");
  Scene tr = s;
  tr.conventions.fill = FillConvention::kTopRight;
  EXPECT_EQ(undeclared(c, tr), "fill convention 'top-right' not declared by the driver");
  // Bad replies name the key and the problem.
  const std::pair<const char*, const char*> bad[] = {
      {R"({"capabilities": {"primitives": ["hexagon"]}})", "primitives: unknown name \"hexagon\""},
      {R"({"capabilities": {"primitives": []}})", "primitives: expected a non-empty array"},
      {R"({"capabilities": {"sample_counts": [3]}})", "sample_counts: 3 is not one of"},
      {R"({"capabilities": {"pipeline": 1}})", "pipeline: expected true or false"},
      {R"({"capabilities": {"colour": true}})", "unknown key \"colour\""},
      {R"({"capabilities": {}, "x": 1})", "expected {\"capabilities\": {...}} and nothing else"},
      {R"({"capabilities": {"max_target_side": 0}})", "max_target_side: expected an integer"},
      {R"({"capabilities": )", "not JSON"},
  };
  for (const auto& [text, want] : bad) {
    const auto r = parse_capabilities(text);
    ASSERT_TRUE(std::holds_alternative<std::string>(r)) << text;
    EXPECT_NE(std::get<std::string>(r).find(want), std::string::npos)
        << text << " -> " << std::get<std::string>(r);
  }
}

// A driver that answers the query with `reply` and draws with the reference otherwise.
std::string replying_driver(const TempDir& dir, const std::string& name, const std::string& reply) {
  return dir.script(name, "if [ \"$RASTRULES_QUERY\" = capabilities ]; then echo '" + reply +
                              "'; exit 0; fi\nexec " + kRender);
}

// rule: DRIVER.EXTERNAL.CAPABILITIES
TEST(ExternalCapabilities, ACampaignDrawsOnlyWhatTheDriverDeclaresAndCountsTheRest) {
  TempDir dir;
  std::string err;
  auto d = open_driver("external:" + replying_driver(dir, "tri.sh",
                                                     R"({"capabilities": {"primitives": )"
                                                     R"(["triangle"], "sample_counts": [1]}})"),
                       &err);
  ASSERT_NE(d, nullptr) << err;
  EXPECT_EQ(d->info().capabilities, "declared");
  EXPECT_TRUE(d->info().triangles);
  EXPECT_FALSE(d->info().points);
  EXPECT_FALSE(d->info().lines_d3d || d->info().lines_bresenham || d->info().lines_rectangular);
  EXPECT_EQ(d->info().sample_counts, std::vector<std::uint32_t>{1});
  fuzzer::Settings s;
  s.driver_name = "external";
  s.cases = 12;
  s.seed = 5;
  const fuzzer::Summary sum = fuzzer::run_fuzz(*d, s);
  EXPECT_TRUE(sum.error.empty()) << sum.error; // no case asked for what it cannot draw
  EXPECT_EQ(sum.cases, 12u);
  EXPECT_EQ(sum.mismatches, 0u);
  // A driver that declares no triangle gets no triangle family: with nothing else declared,
  // every case is skipped rather than failed.
  auto pts = open_driver("external:" + replying_driver(dir, "none.sh",
                                                       R"({"capabilities": {"primitives": )"
                                                       R"(["path"]}})"),
                         &err);
  ASSERT_NE(pts, nullptr) << err;
  s.cases = 4;
  const fuzzer::Summary none = fuzzer::run_fuzz(*pts, s);
  EXPECT_TRUE(none.error.empty()) << none.error;
  EXPECT_EQ(none.skipped, 4u);
}

// rule: DRIVER.EXTERNAL.CAPABILITIES
TEST(ExternalCapabilities, NoReplyDeclaresNothingAndABadReplyIsAnOpenError) {
  TempDir dir;
  std::string err;
  // rastrules render itself does not answer (its standard input is empty): it draws everything.
  auto plain = open_driver("external:" + kRender, &err);
  ASSERT_NE(plain, nullptr) << err;
  EXPECT_EQ(plain->info().capabilities.rfind("none declared", 0), 0u) << plain->info().capabilities;
  EXPECT_TRUE(plain->info().points);
  EXPECT_EQ(plain->unsupported(small_scene()), "");
  err.clear();
  auto bad = open_driver(
      "external:" + replying_driver(dir, "bad.sh", R"({"capabilities": {"lines": true}})"), &err);
  EXPECT_EQ(bad, nullptr);
  EXPECT_NE(err.find("capabilities: unknown key \"lines\""), std::string::npos) << err;
  EXPECT_EQ(err.find('\n'), std::string::npos) << err;
}

} // namespace
} // namespace rastrules::driver
