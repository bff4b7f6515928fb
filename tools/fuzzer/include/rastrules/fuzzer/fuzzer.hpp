// SPDX-License-Identifier: MIT
// The driver fuzzer (spec/driver.md FUZZ.*): seeded scene generators, comparison of a driver's
// coverage with the reference kernel (exact, or legal under a profile), shrinking of every
// mismatch to a minimal scene, and the report (reproducer scenes, pictures, JSON).
// Implements: FUZZ.PROFILE, FUZZ.GENERATE, FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL, FUZZ.SHRINK,
//             FUZZ.REPORT

#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/driver/driver.hpp"
#include "rastrules/profile.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::fuzzer {

// rule: FUZZ.PROFILE
// The kernel's profiles (rastrules/profile.hpp, PROFILE.*), by name.
using Profile = ProfileName;
[[nodiscard]] std::string_view to_string(Profile p); // "d3d11", "vulkan", "opengl"
[[nodiscard]] std::optional<Profile> parse_profile(std::string_view s);

// Sets the conventions the fuzzer varies by profile on a generated scene: the profile's fill
// convention and line mode (rastrules::profile). The other conventions stay the generator's:
// it draws both windings under every cull mode, its own sample patterns and centroid rules,
// and no pipeline state.
// rule: FUZZ.PROFILE
void apply_profile(Profile p, Scene& scene);

// rule: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL
enum class Mode { kExact, kLegal };
[[nodiscard]] std::string_view to_string(Mode m); // "exact", "legal"
[[nodiscard]] std::optional<Mode> parse_mode(std::string_view s);

// A deterministic 64-bit generator (splitmix64).
class Rng {
public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  // Uniform in [lo, hi] (lo <= hi).
  std::int64_t uniform(std::int64_t lo, std::int64_t hi);
  bool chance(std::uint32_t percent) { return uniform(0, 99) < percent; }

private:
  std::uint64_t state_;
};

// A generated case: the scene and the family that produced it.
struct Case {
  Scene scene;
  std::string family; // "random", "shared-edge", "fan", "grid", "sliver", "points", "lines"
};

// Returns case `index` of the campaign with seed `seed`: the same (seed, index) always gives
// the same scene, whatever other cases were drawn. Families the driver cannot draw (per
// info and driver.unsupported()) are not generated; nullopt when no attempt gave a scene
// the driver supports.
// rule: FUZZ.GENERATE
// `only`, when not empty, restricts the families to those named (FUZZ.FAMILIES; the names of
// kFamilies); with it the same (seed, index) may give another scene.
[[nodiscard]] std::optional<Case> generate_case(std::uint64_t seed, std::uint64_t index,
                                                Profile profile, const driver::Driver& driver,
                                                const std::vector<std::string>& only = {});

// The scene families in the order generate_case() draws from them.
// rule: FUZZ.FAMILIES
inline constexpr std::array<std::string_view, 7> kFamilies = {
    "random", "shared-edge", "fan", "grid", "sliver", "points", "lines"};

// The values campaign (`fuzz --values`, FUZZ.VALUES.GENERATE): pipeline scenes with depth
// and 1-3 attributes (perspective, linear, flat; both provoking vertices; d16, d24, d32f):
// `perspective` (clip-space triangles, w ratios up to about 1e6), `clipped` (triangles across
// the near plane or the sides), `strips` (clip-space line strips and lines), `depth` (window
// space, depths near 0 and 1 in the format's resolution). Attributes are small, huge,
// subnormal or large integers. Only for drivers that report values.
// rule: FUZZ.VALUES.GENERATE
inline constexpr std::array<std::string_view, 6> kValueFamilies = {
    "perspective", "clipped", "strips", "depth", "horizon", "bias"};
[[nodiscard]] std::optional<Case> generate_value_case(std::uint64_t seed, std::uint64_t index,
                                                      Profile profile, const driver::Driver& driver,
                                                      const std::vector<std::string>& only = {});
[[nodiscard]] std::vector<std::pair<std::string, std::string>>
value_families_not_generated(Profile profile, const driver::Driver& driver,
                             const std::vector<std::string>& only = {});

// The families generate_case() never draws for this driver and profile, each with the reason.
// rule: FUZZ.GENERATE
[[nodiscard]] std::vector<std::pair<std::string, std::string>>
families_not_generated(Profile profile, const driver::Driver& driver,
                       const std::vector<std::string>& only = {});

// One differing pixel of one primitive: mask holds the samples missing (or extra).
struct DiffEntry {
  std::uint32_t prim = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::uint32_t mask = 0;
  friend bool operator==(const DiffEntry&, const DiffEntry&) = default;
};

// One depth or attribute value of a fragment compared with the exact one (FUZZ.VALUES.*).
struct ValueDiff {
  std::uint32_t prim = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::optional<std::uint32_t> seg, sample, part; // as the reference's fragment has them
  std::string what;                               // "attr NAME" or "depth[K]" (K the sample index)
  std::string rule;     // PIPE.INTERP.PERSPECTIVE, .LINEAR, .FLAT or PIPE.DEPTH.FORMAT
  double expected = 0;  // the exactly rounded value (a float32, or a stored depth: UNORM integer
                        // or float32)
  double reference = 0; // the reference kernel's value (the spec's formula)
  double got = 0;       // the driver's
  double distance = 0;  // from expected: ulps of float32 (attributes, d32f) or UNORM units
  double allowed = 0;   // the mode's allowance in the same unit
  bool within = true;   // the driver's value is allowed
};

// The values of a pipeline scene compared fragment by fragment (FUZZ.VALUES.EXACT,
// FUZZ.VALUES.LEGAL): the fragments both report, matched by (prim, x, y, seg, sample) and the
// part when the driver gives one.
struct ValueComparison {
  std::uint64_t attributes = 0; // attribute values compared
  std::uint64_t depths = 0;     // depth values compared
  std::uint64_t beyond = 0;     // values beyond the mode's allowance
  std::vector<ValueDiff> diffs; // the first kMaxValueDiffs of them, in fragment order
  std::optional<ValueDiff> worst_attribute, worst_depth; // the largest distances, allowed or not
};
inline constexpr std::size_t kMaxValueDiffs = 64;

struct Comparison {
  bool match = false;
  // Pipeline scenes whose driver reports values (DRIVER.VALUES): the values compared; match
  // then also requires that none is beyond the mode's allowance.
  std::optional<ValueComparison> values;
  // Legal mode: the fill conventions under which the driver's result equals the reference
  // (several when the scene has no tie that tells them apart); exact mode: the scene's own
  // when it matches.
  std::vector<FillConvention> conventions;
  FillConvention compared_with = FillConvention::kTopLeft; // the reference shown on a mismatch
  std::vector<Fragment> expected; // the reference under compared_with (observable fields)
  std::vector<Fragment> actual;   // the driver's (observable fields)
  std::vector<DiffEntry> missing; // in expected, not in actual
  std::vector<DiffEntry> extra;   // in actual, not in expected
  // Legal mode: the driver's Bresenham lines differ from the reference's within the deviations
  // Vulkan and OpenGL allow (FUZZ.COMPARE.LEGAL_LINES), and that is what made the case match.
  bool line_allowance = false;
  // Legal mode: some coordinate exactly half a subpixel between two 16.8 values, rounded the
  // other way (FUZZ.COMPARE.LEGAL_TIES), made the case match.
  bool tie_rounding = false;
};

// The rule and the class of a difference, by which findings are grouped.
// rule: FUZZ.GROUP
struct GroupKey {
  std::string rule;  // the rule ID that decided the first differing pixel, e.g. "LINE.VK.EXIT"
  std::string klass; // "<primitive type> <missing|extra|missing+extra>[ 4x]", e.g. "line extra"
  friend auto operator<=>(const GroupKey&, const GroupKey&) = default;
};

// Classifies a mismatch: the rule the reference kernel applied at the first differing pixel
// (missing before extra, each in (prim, y, x) order), decided again on `scene` under the fill
// convention compared with, and the class of the differences of that pixel's primitive.
// rule: FUZZ.GROUP
[[nodiscard]] GroupKey classify(const Scene& scene, const Comparison& comparison);

// Reduces fragments to what every driver can observe: per (prim, x, y) the union of the masks
// of its fragments (segments and per-sample fragments merged, helper lanes dropped), sorted.
[[nodiscard]] std::vector<Fragment> observable(const std::vector<Fragment>& fragments);

// Compares a driver's fragments for a scene with the reference kernel's. In exact mode the
// reference uses the scene as it is; in legal mode under vulkan or opengl any of the four fill
// conventions is accepted (d3d11 allows top-left only). Returns nullopt and sets *error when
// the kernel rejects the scene.
// rule: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL
[[nodiscard]] std::optional<Comparison> compare(const Scene& scene,
                                                const std::vector<Fragment>& actual,
                                                Profile profile, Mode mode, std::string* error);

// Compares a driver's values of a pipeline scene with the exact ones (FUZZ.VALUES.EXACT in exact
// mode, FUZZ.VALUES.LEGAL in legal mode under the profile). nullopt and *error when the kernel
// rejects the scene.
// rule: FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL
[[nodiscard]] std::optional<ValueComparison> compare_values(const Scene& scene,
                                                            const driver::Drawing& drawing,
                                                            Profile profile, Mode mode,
                                                            std::string* error);

// Draws the scene with the driver and compares; nullopt (and *error) when the driver or the
// kernel fails, or the driver does not support the scene.
[[nodiscard]] std::optional<Comparison> draw_and_compare(driver::Driver& driver, const Scene& scene,
                                                         Profile profile, Mode mode,
                                                         std::string* error);

// Returns a minimal scene for which still_differs() holds, starting from `scene` (for which
// it holds): fewest primitives, then fewest strip vertices, then simplest coordinates
// (0, halved integers, integers, halves, 1/16, one pixel toward the origin), one sample, the
// scene moved toward the origin, the smallest target. Deterministic.
// rule: FUZZ.SHRINK
[[nodiscard]] Scene shrink(const Scene& scene,
                           const std::function<bool(const Scene&)>& still_differs);

// The outputs of one mismatch.
struct FindingFiles {
  std::string scene;   // the original scene
  std::string shrunk;  // the shrunk scene
  std::string picture; // expected | actual | difference of the shrunk scene
  std::string report;  // the JSON report of this finding
};

struct Finding {
  std::uint64_t case_index = 0;
  std::string family;
  Scene original;
  Scene shrunk;
  Comparison comparison; // of the shrunk scene
  std::string key;       // the shrunk scene's text: equal keys are the same shrunk scene
  std::optional<std::uint64_t> duplicate_of; // case index of the first finding with this key
  GroupKey group;                            // FUZZ.GROUP
  FindingFiles files;
};

// Findings with one GroupKey: how many, and the first (lowest case) as the example.
// rule: FUZZ.GROUP, FUZZ.BASELINE
struct Group {
  GroupKey key;
  std::uint64_t count = 0;        // mismatching cases
  std::uint64_t scenes = 0;       // distinct shrunk scenes
  std::uint64_t example_case = 0; // the first case of the group
  std::string example;            // its shrunk scene (text)
  std::string picture;            // its picture, when written
  bool known = false;             // in the baseline
  std::string known_as;           // the baseline entry's "finding" (a FINDING.* ID), if any
};

// Builds the groups of a list of findings (in case order), sorted by key.
// rule: FUZZ.GROUP
[[nodiscard]] std::vector<Group> group_findings(const std::vector<Finding>& findings);

// Known findings (FUZZ.BASELINE): a JSON file {"version": 1, "known": [{"rule": ID,
// "class": CLASS, "finding": FINDING.ID (optional), "note": TEXT (optional)}, ...]}.
struct BaselineEntry {
  GroupKey key;
  std::string finding;
  std::string note;
};
struct Baseline {
  std::string path;
  std::vector<BaselineEntry> known;
};

// Reads a baseline; nullopt and *error ("PATH: known[2].rule: ...") when it is not one.
// rule: FUZZ.BASELINE
[[nodiscard]] std::optional<Baseline> read_baseline(const std::string& path, std::string* error);

// Campaign settings (rastrules fuzz / rastrules check).
struct Settings {
  std::string driver_name;
  Profile profile = Profile::kD3D11;
  Mode mode = Mode::kExact;
  std::uint64_t seed = 1;
  std::uint64_t cases = 100;
  std::string out_dir;   // empty: write nothing
  bool progress = false; // draw a progress bar on standard error
  // rule: FUZZ.SHARD
  // Shard shard_index of shard_count: the campaign runs the cases i < cases with
  // i % shard_count == shard_index (the same scenes as the unsharded campaign).
  std::uint64_t shard_index = 0;
  std::uint64_t shard_count = 1;
  // rule: FUZZ.FAMILIES
  std::vector<std::string> families; // `--families`: only these (names of kFamilies); empty: all
  // rule: FUZZ.VALUES.GENERATE
  bool values = false; // `--values`: the values campaign (kValueFamilies)
};

// The cases of one scene family and how many of them mismatched.
struct FamilyCount {
  std::uint64_t cases = 0;
  std::uint64_t mismatches = 0;
};

struct Summary {
  std::uint64_t cases = 0;   // cases drawn and compared
  std::uint64_t skipped = 0; // cases the driver could not draw
  std::uint64_t mismatches = 0;
  std::uint64_t unique = 0;         // distinct shrunk scenes
  std::uint64_t line_allowance = 0; // legal mode: cases that match by FUZZ.COMPARE.LEGAL_LINES
  std::uint64_t tie_rounding = 0;   // legal mode: cases that match by FUZZ.COMPARE.LEGAL_TIES
  double seconds = 0;
  std::vector<Finding> findings;
  std::vector<Group> groups;                   // FUZZ.GROUP, after the campaign
  std::vector<std::uint64_t> skipped_cases;    // the cases counted in skipped
  std::map<std::string, FamilyCount> families; // compared cases by family
  // Families never generated for this driver and profile, and why (FUZZ.GENERATE).
  std::vector<std::pair<std::string, std::string>> families_not_generated;
  std::vector<std::pair<FillConvention, std::uint64_t>> legal_conventions; // legal mode: chosen
  // rule: FUZZ.VALUES.REPORT
  // Values compared over the campaign (drivers that report them) and the largest distances.
  std::uint64_t value_attributes = 0, value_depths = 0;
  std::uint64_t value_cases = 0; // cases whose values were compared
  std::optional<ValueDiff> worst_attribute, worst_depth;
  std::uint64_t worst_attribute_case = 0, worst_depth_case = 0;
  std::string error;        // non-empty: the campaign stopped on a driver error
  bool interrupted = false; // SIGINT or SIGTERM: the campaign stopped after its case
  std::string report_path;
};

// Marks the groups the baseline knows; returns the number of groups it does not know.
// rule: FUZZ.BASELINE
std::uint64_t apply_baseline(const Baseline& baseline, Summary& s);

// The machine-readable results of a campaign (FUZZ.RESULTS): JUnit XML, one test case per
// finding group (a failure unless the baseline knows it) and one per scene family of the
// generated cases; and the JSON summary (cases run and skipped, groups, baseline matches).
// `baseline` may be null.
// rule: FUZZ.RESULTS
[[nodiscard]] std::string junit_xml(const Settings& settings, const Summary& s,
                                    const Baseline* baseline);
[[nodiscard]] std::string summary_json(const Settings& settings, const std::string& description,
                                       const Summary& s, const Baseline* baseline);

// Joins the report.json files of shard campaigns (FUZZ.SHARD) into the campaign they split:
// every finding of every shard, in case order, deduplicated and grouped again as one campaign
// would. Fills *settings from the reports (which must agree on driver, profile, mode, seed,
// cases and shard count, with each shard present once); nullopt and *error otherwise.
// rule: FUZZ.MERGE
[[nodiscard]] std::optional<Summary> merge_reports(const std::vector<std::string>& dirs,
                                                   Settings* settings, std::string* description,
                                                   std::string* error);

// Writes DIR/report.json for a summary (what a campaign writes at its end).
// rule: FUZZ.REPORT
[[nodiscard]] std::optional<std::string> write_report(const Settings& settings,
                                                      const std::string& description, Summary& s);

// Writes the picture of a comparison: expected | actual | difference, side by side, magnified,
// with the pixel grid, the snapped edges and the sample points. Returns an error or nullopt.
// rule: FUZZ.REPORT
[[nodiscard]] std::optional<std::string>
write_difference_png(const std::string& path, const Scene& scene, const Comparison& comparison);

// Runs a campaign of settings.cases generated cases.
// rule: FUZZ.GENERATE, FUZZ.SHRINK, FUZZ.REPORT
[[nodiscard]] Summary run_fuzz(driver::Driver& driver, const Settings& settings);

// Compares one scene (the same outputs as a campaign of one case).
[[nodiscard]] Summary run_check(driver::Driver& driver, const Scene& scene,
                                const Settings& settings);

// What `rastrules probe` found out about a driver's conventions (spec/driver.md FUZZ.PROBE).
struct ProbeReport {
  // Fill convention: whether samples exactly on a top, bottom, left, right edge are inside.
  bool top = false, bottom = false, left = false, right = false;
  std::string fill; // "top-left", ..., or a description when no convention fits
  // Snapping: the threshold (in 1/4096 px) from a pixel centre at which an edge leaves the
  // centre's snapped position, the subpixel bits and rounding it implies.
  std::int64_t threshold_4096 = 0;
  int subpixel_bits = -1; // -1: not determined
  std::string rounding;   // "round half to even", ...
  std::string line_mode;  // the line modes matching the probe lines, or why not probed
  std::string point_rule; // whether points match POINT.SHAPE.SQUARE, or why not probed
  std::vector<SampleOffset> samples_4x; // the 4x positions found (1/16 px), empty: not probed
  std::string samples_note;
  std::string error; // non-empty: a draw failed
};

// Probes the driver with small scenes (half-planes through pixel centres, binary search of
// snapping thresholds, per-sample scans).
// rule: FUZZ.PROBE
[[nodiscard]] ProbeReport probe(driver::Driver& driver);

// Prints the summary table and one line per finding group (FUZZ.GROUP).
void print_summary(std::FILE* out, const Settings& settings, const driver::Driver& driver,
                   const Summary& s);
// capabilities: how an external driver's capabilities were learnt (DriverInfo::capabilities),
// printed under the driver when not empty.
void print_summary(std::FILE* out, const Settings& settings, const std::string& description,
                   const Summary& s, const std::string& capabilities = {});

} // namespace rastrules::fuzzer
