// SPDX-License-Identifier: MIT
// Shared pieces of the rastrules command line: exit codes, error reporting, scene loading,
// output files that appear only when complete.
// Implements: SCENE.INPUT.ERRORS

#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/io/output_file.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::cli {

// rule: SCENE.INPUT.ERRORS
inline constexpr int kExitOk = 0;
inline constexpr int kExitDifference = 1; // a difference was found (showcase vs the oracle)
inline constexpr int kExitBadInput = 2;   // bad input or usage

using Args = std::vector<std::string>;

// Prints "rastrules: error: MESSAGE" as one line on standard error. Returns kExitBadInput.
int error(std::string_view message);

// Prints "rastrules: error: REASON" and the hint "run 'rastrules COMMAND --help'" (the command
// being parsed, or 'rastrules --help' before one is known) on standard error, never the whole
// help. Returns kExitBadInput.
// rule: SCENE.INPUT.ERRORS
int usage_error(std::string_view reason);

// The command whose options are being read, named by usage_error()'s hint ("" before one).
void set_current_command(std::string_view command);

// How much a command says besides errors and results: -q (quiet: no progress or summary
// text), -v (verbose: more detail where a command has it, e.g. a campaign's progress).
enum class Verbosity { kQuiet, kNormal, kVerbose };
Verbosity verbosity();
void set_verbosity(Verbosity v);

// Prints the overview of the commands (rastrules --help) on `out`.
void print_usage(std::FILE* out);

// The project's version (CMake's project(VERSION)) and the scene format's (SCENE.FORMAT.V1),
// as `rastrules --version` prints them.
inline constexpr int kSceneFormatVersion = 1;

// A scene read from a file; prepared by the kernel when it has no pipeline state (a scene with
// pipeline state is validated and drawn by rastrules::pipe::run_pipeline()).
struct LoadedScene {
  Scene scene;
  std::optional<PreparedScene> prepared;
};

// Reads, parses and, without pipeline state, prepares a scene ("-" is standard input). On
// failure prints the one-line error (`rastrules: error: FIELD: PROBLEM`) and returns nullopt.
// rule: SCENE.INPUT.ERRORS
std::optional<LoadedScene> load_scene(const std::string& path);

// load_scene(path) in two steps: the file's text (or nullopt after printing the error naming
// the file), then the scene read from that text (errors printed as load_scene(path) prints
// them, a parse error naming the file `path`).
// rule: SCENE.INPUT.ERRORS
std::optional<io::SceneText> read_scene_text(const std::string& path);
std::optional<LoadedScene> load_scene_text(std::string_view text, const std::string& path);

// What load_scene() does after reading: a scene with pipeline state validated
// (pipe::validate), any other prepared. Returns the loaded scene or the first error.
// rule: SCENE.INPUT.ERRORS
std::variant<LoadedScene, SceneError> load_scene(Scene scene);

// Runs the pipeline on a scene read by load_scene(); on bad input (run_pipeline's SceneError,
// also more than max_fragments fragments or max_work sample tests) prints the one-line error
// and returns nullopt. plain: every optimization off (PipeOptions::plain(), `render
// --pipeline-plain`).
// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
std::optional<pipe::PipeResult> run_pipeline_or_report(const Scene& scene,
                                                       const RenderOptions& options,
                                                       std::uint64_t max_fragments,
                                                       bool plain = false,
                                                       std::uint64_t max_work = kDefaultMaxWork);

// Output files (OutputFile, same_output_file, write_text) are rastrules::io's, shared with the
// fuzzer's reports.
// What the work limit's error adds to the kernel's words (work_limit_problem), for coverage and
// pipeline scenes alike.
// rule: SCENE.INPUT.LIMITS
inline constexpr std::string_view kMaxWorkHint = "; raise it with --max-work N";
// The same for the fragment limit (--max-fragments).
inline constexpr std::string_view kMaxFragmentsHint = "; raise it with --max-fragments N";

// An option's value as an error message shows it: "\"VALUE\"" with bytes outside printable
// ASCII written as \xNN and cut to 40 bytes (io::printable), or "nothing" when it is missing.
// rule: SCENE.INPUT.ERRORS
[[nodiscard]] std::string shown_value(const std::optional<std::string>& v);

using io::OutputFile;
using io::same_output_file;
using io::write_text;

// The one scene file among the arguments of `command` (render, explain) that no option took.
// Returns nullopt when there is exactly one, else the exit status of the usage error (none, a
// second scene file).
std::optional<int> take_scene_argument(std::string_view command,
                                       const std::vector<std::string>& positionals,
                                       std::string& scene_path);

// Parses a decimal integer in [lo, hi]; nullopt when the text is anything else.
std::optional<std::int64_t> parse_int(std::string_view text, std::int64_t lo, std::int64_t hi);

int run_render(const Args& args);
int run_explain(const Args& args);
int run_showcase(const Args& args);
int run_fuzz(const Args& args);
int run_check(const Args& args);
int run_fuzz_merge(const Args& args);
int run_probe(const Args& args);
// rastrules fuzz2d: the 2D campaign against a 2D library (FUZZ.PATH.*).
int run_fuzz2d(const Args& args);
int run_bench(const Args& args);
int run_glyph(const Args& args); // glyph.cpp: a glyph of a font file as a path scene
int run_cases(const Args& args); // cases.cpp: the hard-case catalog (PIPE.CATALOG)

} // namespace rastrules::cli
