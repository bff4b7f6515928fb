// SPDX-License-Identifier: MIT
// Shared pieces of the rastrules command line.
// Implements: SCENE.INPUT.ERRORS

#include "cli.hpp"

#include <charconv>
#include <filesystem>
#include <variant>

#include "rastrules/io/scene_json.hpp"

namespace rastrules::cli {

int error(std::string_view message) {
  // One line, whatever the message holds.
  std::string line = "rastrules: error: ";
  for (const char c : message)
    line += (c == '\n' || c == '\r') ? ' ' : c;
  line += '\n';
  std::fputs(line.c_str(), stderr);
  return kExitBadInput;
}

void print_usage(std::FILE* out) {
  std::fputs(
      "usage: rastrules [-q|-v] <command> [options]\n"
      "       rastrules help COMMAND (or rastrules COMMAND --help): the command's options\n"
      "       rastrules --version\n"
      "\n"
      "commands:\n"
      "  render SCENE.json [--fragments OUT.json] [--png OUT.png] [--scale N]\n"
      "         [--resolve OUT.png] [--max-fragments N] [--max-work N] [--threads N]\n"
      "         [--traversal plain|fast] [--isa scalar|avx2|avx512|auto]\n"
      "         [--png-depth] [--depth-out OUT.json] [--pipeline-plain]\n"
      "      Rasterize a scene (spec/scene.md). --fragments writes the fragment list,\n"
      "      sorted by (prim, y, x); --png draws the target magnified N times (default 32,\n"
      "      less for large targets; at most 4096 pixels a side) with the pixel grid, pixel\n"
      "      centres, the snapped edges, covered pixels coloured by primitive and overlaps\n"
      "      hatched in red; for multisampled scenes (at N >= 8) every sample point, covered\n"
      "      samples filled, helper lanes outlined dashed and centroids marked. --resolve\n"
      "      writes the resolved target as an RGBA PNG (MSAA.RESOLVE.AVERAGE; at most\n"
      "      2^26 samples in all, MSAA.LIMITS). At least one output is needed. \"-\" reads\n"
      "      the scene from standard input or writes one output to standard output. More\n"
      "      than --max-fragments fragments (default 67108864) is an error, and so is\n"
      "      more work than --max-work sample tests (default 68719476736: the pixels of\n"
      "      each triangle's bounding box, counted before any is drawn)\n"
      "      (SCENE.INPUT.LIMITS). --threads N (1 to 256, default 1) renders with N\n"
      "      threads, the same bytes as with one (FAST.THREADS.DETERMINISTIC);\n"
      "      --traversal (default fast) and --isa (default auto: the widest the processor\n"
      "      runs) choose the coverage traversal, never the result (FAST.EQUALS.PLAIN).\n"
      "      Pipeline scenes (SCENE.PIPELINE: clip-space \"pos\", \"transform\", \"viewport\",\n"
      "      \"depth\", \"attributes\") go through the pipeline: fragments also carry \"part\",\n"
      "      \"bary\", \"attr\", \"depth\" and \"passed\" as the scene asks\n"
      "      (SCENE.OUTPUT.PIPELINE); --png-depth draws the final depth buffer in grey\n"
      "      (black near, white far) instead of coverage; --depth-out writes it as JSON;\n"
      "      --resolve writes the samples that passed the depth test. --pipeline-plain\n"
      "      turns off every optimization (PIPE.OPT.*: binning, Hi-Z, early-Z, fast\n"
      "      clear, and the fast traversal), never changing the result.\n"
      "  explain SCENE.json --pixel X,Y [--json]\n"
      "      For every primitive: its snapped vertices, area, winding, culling, and for each\n"
      "      edge the exact edge value at the centre of pixel (X, Y), whether it is a top or\n"
      "      left edge, and the rule that decided; then whether the pixel is covered. For a\n"
      "      multisampled scene, the same for every sample of the pixel, then the coverage\n"
      "      mask, the sample mask, the fragment's mask and the centroid branch. For a\n"
      "      pipeline scene, the fragments run_pipeline produces at the pixel (part,\n"
      "      barycentrics, attributes, depths, depth test). For a path, each sample's\n"
      "      crossings (by contour and segment), winding number and fill rule's verdict,\n"
      "      and the pixel's exact area.\n"
      "  showcase --out DIR [--json]\n"
      "      Render the built-in showcase scenes into DIR (scene, fragments and picture of\n"
      "      each, and the resolved target of multisampled ones), compare every one with\n"
      "      the exact oracle and print a summary.\n"
      "  fuzz --driver NAME [--profile d3d11|vulkan|opengl] [--mode exact|legal]\n"
      "       [--cases N] [--seed S] [--shard K/N] [--out DIR] [--no-progress]\n"
      "       [--baseline KNOWN.json] [--junit FILE.xml] [--summary-json FILE.json]\n"
      "      Draw N generated scenes (default 100, seed 1, profile d3d11, mode exact) with\n"
      "      the driver and compare each with the reference; every mismatch is shrunk to a\n"
      "      minimal scene and, with --out, written as DIR/case-N.scene.json (original),\n"
      "      case-N.min.json (shrunk), case-N.png (expected | actual | difference) and\n"
      "      case-N.json, with DIR/report.json for the campaign (spec/driver.md FUZZ.*).\n"
      "      Drivers: reference, imprecise[:float-edges|:fill-bottom-right|:4-bit-subpixel],\n"
      "      lavapipe and opengl (when built), external:COMMAND (DRIVER.EXTERNAL.PROTOCOL);\n"
      "      2D libraries (paths only, for fuzz2d): freetype, cairo, agg, skia, tiny-skia.\n"
      "      Mismatches are grouped by the rule that decided them and their class; with\n"
      "      --baseline only groups the file does not list fail (FUZZ.BASELINE). --junit\n"
      "      and --summary-json write JUnit XML and a JSON summary (FUZZ.RESULTS). --shard\n"
      "      K/N runs the cases i with i mod N = K (FUZZ.SHARD).\n"
      "  fuzz-merge DIR... [--out DIR] [--baseline F] [--junit F] [--summary-json F]\n"
      "      Join the --out DIRs of the N shards of a campaign into that campaign\n"
      "      (FUZZ.MERGE): the summary, groups, exit status and outputs of fuzz.\n"
      "  check SCENE.json --driver NAME [--profile P] [--mode exact|legal] [--out DIR]\n"
      "        [--baseline F] [--junit F] [--summary-json F]\n"
      "      The same comparison and outputs for one scene, used as it is.\n"
      "  probe --driver NAME [--json]\n"
      "      Report the driver's fill convention, subpixel bits and snapping rounding, line\n"
      "      mode, point rule and 4x sample positions, found with probe scenes.\n"
      "  fuzz2d --driver NAME [--cases N] [--seed S] [--out DIR] [--alpha-tolerance N]\n"
      "         [--families A,B] [--max-findings N] [--exact]\n"
      "      Draw generated paths with a 2D library (freetype, cairo, agg, skia, tiny-skia,\n"
      "      imprecise-path:BUG) and compare with the exact coverage (FUZZ.PATH.*): ties\n"
      "      and alpha within the tolerance are legal, other differences are classified\n"
      "      and shrunk, with pictures and DIR/report.json.\n"
      "  bench --ladder [--out DIR] [--quick] [--seed N] [--threads N]\n"
      "      The precision ladder (spec/bench.md): the same scenes rasterized by float,\n"
      "      double, scanline, 4-bit/32-bit, the reference (plain and fast), 16-bit/128-bit\n"
      "      and the exact oracle, with speed (ratios to the reference), errors,\n"
      "      watertightness, translation invariance and lavapipe's time; prints the table\n"
      "      and with --out writes DIR/ladder.md, ladder.json and ladder.png. The fast\n"
      "      path is also timed on --threads N threads (default: one per processor).\n"
      "  cases [DIR] [--json]\n"
      "      Check the hard-case catalog (default spec/cases, PIPE.CATALOG): each case run\n"
      "      with and without the optimizations, its values against the exact oracle's\n"
      "      bounds and its NAME.expect.json; one line per case, exit status 1 on a failure.\n"
      "  glyph FONT --char C [--size N] [--coverage samples|area] [--out SCENE.json]\n"
      "      Write a glyph of a font file (C: one character or U+XXXX; N px, default 64)\n"
      "      as a path scene (SCENE.PRIM.PATH) through FreeType's unhinted outline, exactly\n"
      "      (PATH.GLYPH.SOURCE), to standard output or SCENE.json. Built with FreeType.\n"
      "  help [COMMAND]\n"
      "      Show this text (also --help, -h), or COMMAND's options.\n"
      "\n"
      "every command: -h/--help, -q/--quiet (errors and results only), -v/--verbose (more\n"
      "detail, e.g. a campaign's progress); --opt VALUE or --opt=VALUE; --json (explain,\n"
      "showcase, probe, cases) prints one JSON document instead of the text.\n"
      "exit status: 0 success, 1 a difference was found (showcase, fuzz, check, fuzz-merge,\n"
      "cases; with --baseline: one it does not list), 2 bad "
      "input\n"
      "or usage, or a driver failure.\n",
      out);
}

namespace {
std::string& current_command() {
  static std::string command;
  return command;
}
Verbosity& current_verbosity() {
  static Verbosity v = Verbosity::kNormal;
  return v;
}
} // namespace

void set_current_command(std::string_view command) {
  current_command() = command;
}
Verbosity verbosity() {
  return current_verbosity();
}
void set_verbosity(Verbosity v) {
  current_verbosity() = v;
}

// rule: SCENE.INPUT.ERRORS
int usage_error(std::string_view reason) {
  error(reason);
  const std::string& c = current_command();
  std::fprintf(stderr, "run 'rastrules %s--help'\n", c.empty() ? "" : (c + " ").c_str());
  return kExitBadInput;
}

// rule: SCENE.INPUT.ERRORS
std::optional<LoadedScene> load_scene(const std::string& path) {
  const std::optional<io::SceneText> text = read_scene_text(path);
  if (!text)
    return std::nullopt;
  return load_scene_text(text->view(), path);
}

// rule: SCENE.INPUT.ERRORS
std::optional<io::SceneText> read_scene_text(const std::string& path) {
  auto text = io::open_scene_file(path);
  if (auto* err = std::get_if<SceneError>(&text)) {
    error(err->what());
    return std::nullopt;
  }
  return std::move(std::get<io::SceneText>(text));
}

// rule: SCENE.INPUT.ERRORS
std::optional<LoadedScene> load_scene_text(std::string_view text, const std::string& path) {
  auto scene = io::read_scene(text);
  if (auto* err = std::get_if<SceneError>(&scene)) {
    // Parse errors have no field: the file is named instead.
    error(err->field.empty() ? (path == "-" ? "<stdin>" : path) + ": " + err->message
                             : err->what());
    return std::nullopt;
  }
  auto loaded = load_scene(std::move(std::get<Scene>(scene)));
  if (auto* err = std::get_if<SceneError>(&loaded)) {
    error(err->what());
    return std::nullopt;
  }
  return std::move(std::get<LoadedScene>(loaded));
}

// rule: SCENE.INPUT.ERRORS
std::variant<LoadedScene, SceneError> load_scene(Scene scene) {
  auto checked = pipe::check_scene(scene);
  if (auto* err = std::get_if<SceneError>(&checked))
    return *err;
  return LoadedScene{std::move(scene), std::move(std::get<std::optional<PreparedScene>>(checked))};
}

// rule: SCENE.INPUT.ERRORS
std::string shown_value(const std::optional<std::string>& v) {
  return v ? "\"" + io::printable(*v, 40) + "\"" : std::string("nothing");
}

// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
std::optional<pipe::PipeResult> run_pipeline_or_report(const Scene& scene,
                                                       const RenderOptions& options,
                                                       std::uint64_t max_fragments, bool plain,
                                                       std::uint64_t max_work) {
  // rule: PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR
  pipe::PipeOptions o;
  o.render = options;
  if (plain) {
    o = pipe::PipeOptions::plain();
    o.render.threads = options.threads;
    o.render.isa = options.isa;
  }
  o.max_fragments = max_fragments;
  o.max_work = max_work;
  auto result = pipe::run_pipeline(scene, o);
  if (auto* err = std::get_if<SceneError>(&result)) {
    // rule: SCENE.INPUT.LIMITS
    const std::string_view hint = err->kind == SceneError::Kind::kWorkLimit ? kMaxWorkHint
                                  : err->kind == SceneError::Kind::kFragmentLimit
                                      ? kMaxFragmentsHint
                                      : "";
    error(err->what() + std::string(hint));
    return std::nullopt;
  }
  return std::move(std::get<pipe::PipeResult>(result));
}

std::optional<int> take_scene_argument(std::string_view command,
                                       const std::vector<std::string>& positionals,
                                       std::string& scene_path) {
  const std::string prefix = std::string(command) + ": ";
  if (positionals.empty())
    return usage_error(prefix + "missing SCENE.json");
  if (positionals.size() > 1)
    return usage_error(prefix + "more than one scene file");
  scene_path = positionals.front();
  return std::nullopt;
}

std::optional<std::int64_t> parse_int(std::string_view text, std::int64_t lo, std::int64_t hi) {
  std::int64_t v = 0;
  const char* last = text.data() + text.size();
  const auto r = std::from_chars(text.data(), last, v);
  if (text.empty() || r.ec != std::errc{} || r.ptr != last || v < lo || v > hi)
    return std::nullopt;
  return v;
}

} // namespace rastrules::cli
