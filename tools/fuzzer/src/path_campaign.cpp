// SPDX-License-Identifier: MIT
// The 2D campaign against one library (FUZZ.PATH.*): generate, draw, compare with the exact
// coverage, shrink the first findings of each class, write the report and pictures, and time
// the library against the exact kernel on the same scenes.
// Implements: FUZZ.PATH.REPORT

#include <chrono>
#include <filesystem>
#include <variant>

#include <nlohmann/json.hpp>

#include "rastrules/fuzzer/paths.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/interrupt.hpp"
#include "rastrules/io/output_file.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::fuzzer::paths {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Draws and compares; nullopt with *error on a driver or kernel failure.
std::optional<PathComparison> draw_compare(driver::Driver& d, const Scene& scene,
                                           const PathCompareOptions& o, std::string* error,
                                           double* seconds = nullptr) {
  const auto t = Clock::now();
  driver::DrawResult r = d.draw(scene);
  if (seconds != nullptr)
    *seconds += since(t);
  if (const auto* e = std::get_if<driver::DriverError>(&r)) {
    *error = e->message;
    return std::nullopt;
  }
  return compare_paths(scene, std::get<std::vector<Fragment>>(r), o, error);
}

nlohmann::json diff_json(const PixelDiff& d) {
  return {{"prim", d.prim},     {"x", d.x},
          {"y", d.y},           {"expected", d.expected},
          {"actual", d.actual}, {"class", std::string(to_string(d.klass))},
          {"why", d.why}};
}

std::string class_slug(DiffClass c) {
  std::string s(to_string(c));
  for (char& ch : s)
    if (ch == ' ')
      ch = '-';
  return s;
}

// rule: FUZZ.PATH.COMPARE
// The boundary conventions consistent with every tie pixel of a campaign, as text.
std::string conventions_text(std::uint8_t mask, std::uint64_t tie_pixels) {
  if (tie_pixels == 0)
    return "no pixel centre on a boundary was drawn";
  std::string names;
  for (std::size_t k = 0; k < 4; ++k)
    if ((mask >> k) & 1u)
      names += (names.empty() ? "" : ", ") + std::string(to_string(static_cast<FillConvention>(k)));
  return (names.empty() ? std::string("no single convention of PATH.SAMPLE.TIE")
                        : "consistent with " + names) +
         " (over " + std::to_string(tie_pixels) + " pixels whose centre is on a boundary)";
}

} // namespace

// rule: FUZZ.PATH.REPORT
std::optional<std::string> write_path_picture(const std::string& file, const Scene& scene,
                                              const PathComparison& c) {
  if (c.expected.empty())
    return std::nullopt;
  const int w = scene.width, h = scene.height;
  const int scale = std::max(4, std::min(48, 480 / std::max(1, std::max(w, h))));
  const int gap = 8;
  const int pw = w * scale;
  io::Image img(3 * pw + 2 * gap, h * scale, {255, 255, 255});
  const auto& e = c.expected.front();
  const auto& a = c.actual.front();
  auto level = [&](std::uint8_t v) {
    const int l = c.antialiased ? v : (v != 0 ? 255 : 0);
    return static_cast<std::uint8_t>(255 - l);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
      const std::uint8_t le = level(e[i]), la = level(a[i]);
      img.fill_rect(x * scale, y * scale, (x + 1) * scale, (y + 1) * scale, {le, le, le});
      img.fill_rect(pw + gap + x * scale, y * scale, pw + gap + (x + 1) * scale, (y + 1) * scale,
                    {la, la, la});
      // Difference: red where the library has more, blue where less, by how much.
      const int d =
          (c.antialiased ? a[i] : (a[i] ? 255 : 0)) - (c.antialiased ? e[i] : (e[i] ? 255 : 0));
      const auto k = static_cast<std::uint8_t>(255 - std::min(255, std::abs(d) * 4));
      const io::Rgb col = d > 0   ? io::Rgb{255, k, k}
                          : d < 0 ? io::Rgb{k, k, 255}
                                  : io::Rgb{255, 255, 255};
      img.fill_rect(2 * (pw + gap) + x * scale, y * scale, 2 * (pw + gap) + (x + 1) * scale,
                    (y + 1) * scale, col);
    }
  // On every panel: the pixel grid, the pixel centres and the path's boundary (each curve drawn
  // as 32 chords: a picture, not a decision).
  const Primitive* prim = scene.primitives.empty() ? nullptr : &scene.primitives.front();
  for (int panel = 0; panel < 3; ++panel) {
    const double x0 = panel * (pw + gap);
    for (int x = 0; x <= w; ++x)
      img.line(x0 + std::min(x * scale, pw - 1), 0, x0 + std::min(x * scale, pw - 1), h * scale - 1,
               {170, 170, 170});
    for (int y = 0; y <= h; ++y)
      img.line(x0, std::min(y * scale, h * scale - 1), x0 + pw - 1,
               std::min(y * scale, h * scale - 1), {170, 170, 170});
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        img.disc(static_cast<int>(x0) + x * scale + scale / 2, y * scale + scale / 2, 1,
                 {120, 120, 120}, true);
    if (prim == nullptr || !prim->path)
      continue;
    auto to_img = [&](const FloatPoint& q) {
      return std::array<double, 2>{x0 + static_cast<double>(q[0]) * scale,
                                   static_cast<double>(q[1]) * scale};
    };
    for (const FloatContour& contour : prim->path->contours) {
      FloatPoint cur = contour.start;
      auto chord = [&](const FloatPoint& from, const FloatPoint& to) {
        const auto pa = to_img(from), pb = to_img(to);
        img.line(pa[0], pa[1], pb[0], pb[1], {200, 30, 30});
      };
      for (const FloatPathSegment& seg : contour.segments) {
        const std::size_t n = path::point_count(seg.kind);
        std::array<FloatPoint, 4> ctl = {cur, seg.p[0], seg.p[1], seg.p[2]};
        FloatPoint prev = cur;
        const int pieces = n == 1 ? 1 : 32;
        for (int k = 1; k <= pieces; ++k) {
          const double t = static_cast<double>(k) / pieces, u = 1 - t;
          double bx = 0, by = 0;
          if (n == 1) {
            bx = ctl[1][0];
            by = ctl[1][1];
          } else if (n == 2) {
            bx = u * u * ctl[0][0] + 2 * u * t * ctl[1][0] + t * t * ctl[2][0];
            by = u * u * ctl[0][1] + 2 * u * t * ctl[1][1] + t * t * ctl[2][1];
          } else {
            bx = u * u * u * ctl[0][0] + 3 * u * u * t * ctl[1][0] + 3 * u * t * t * ctl[2][0] +
                 t * t * t * ctl[3][0];
            by = u * u * u * ctl[0][1] + 3 * u * u * t * ctl[1][1] + 3 * u * t * t * ctl[2][1] +
                 t * t * t * ctl[3][1];
          }
          const FloatPoint next{static_cast<float>(bx), static_cast<float>(by)};
          chord(prev, next);
          prev = next;
        }
        cur = seg.p[n - 1];
      }
      chord(cur, contour.start);
    }
  }
  io::OutputFile out;
  if (auto err = out.open(file))
    return file + ": " + *err;
  if (auto err = io::write_png(out.get(), img))
    return file + ": " + *err;
  if (auto err = out.commit())
    return file + ": " + *err;
  return std::nullopt;
}

// rule: FUZZ.PATH.GENERATE, FUZZ.PATH.SHRINK, FUZZ.PATH.REPORT
PathSummary run_path_fuzz(driver::Driver& driver, const PathSettings& settings) {
  PathSummary s;
  const auto start = Clock::now();
  std::string error;
  auto reference = driver::open_driver("reference", &error);
  if (!settings.out_dir.empty())
    std::filesystem::create_directories(settings.out_dir);
  std::array<std::uint64_t, kDiffClassCount> shrunk{};
  for (std::uint64_t i = 0; i < settings.cases; ++i) {
    // rule: FUZZ.PATH.REPORT
    // An interrupt stops the campaign between cases (and a shrink between draws); the report
    // holds what it has.
    if (io::interrupted()) {
      s.interrupted = true;
      break;
    }
    auto c = generate_path_case(settings.seed, i, driver.info(), settings.families);
    if (!c || !driver.unsupported(c->scene).empty()) {
      ++s.skipped;
      continue;
    }
    ++s.cases;
    auto& fam = s.families[c->family];
    ++fam.first;
    auto cmp = draw_compare(driver, c->scene, settings.compare, &error, &s.driver_seconds);
    if (!cmp) {
      if (io::interrupted()) { // the driver's process was ended by the interrupt
        s.interrupted = true;
        break;
      }
      s.error = "case " + std::to_string(i) + ": " + error;
      break;
    }
    {
      const auto t = Clock::now();
      (void)reference->draw(c->scene);
      s.reference_seconds += since(t);
    }
    s.pixels += cmp->pixels;
    s.legal_ties += cmp->legal_ties;
    s.tie_pixels += cmp->tie_pixels;
    s.conventions = static_cast<std::uint8_t>(s.conventions & cmp->conventions);
    s.within += cmp->within;
    s.max_alpha_error = std::max(s.max_alpha_error, cmp->max_alpha_error);
    for (std::size_t k = 0; k < kDiffClassCount; ++k)
      s.pixels_by_class[k] += cmp->by_class[k];
    if (cmp->match)
      continue;
    ++s.mismatches;
    ++fam.second;
    const DiffClass klass = cmp->main_class();
    ++s.cases_by_class[static_cast<std::size_t>(klass)];
    if (shrunk[static_cast<std::size_t>(klass)] >= settings.max_findings)
      continue;
    ++shrunk[static_cast<std::size_t>(klass)];
    PathFinding f;
    f.case_index = i;
    f.family = c->family;
    f.klass = klass;
    f.original = c->scene;
    f.shrunk = shrink_path(c->scene, driver.info().paths.grid_raw, [&](const Scene& t) {
      if (io::interrupted() || !driver.unsupported(t).empty())
        return false;
      std::string ignored;
      auto r = draw_compare(driver, t, settings.compare, &ignored);
      return r && r->by_class[static_cast<std::size_t>(klass)] > 0;
    });
    if (auto r = draw_compare(driver, f.shrunk, settings.compare, &error))
      f.comparison = std::move(*r);
    if (!settings.out_dir.empty()) {
      const std::filesystem::path dir(settings.out_dir);
      const std::string stem = "case-" + std::to_string(i) + "-" + class_slug(klass);
      f.scene_file = (dir / (stem + ".json")).string();
      f.shrunk_file = (dir / (stem + "-shrunk.json")).string();
      f.picture_file = (dir / (stem + "-shrunk.png")).string();
      if (auto err = io::write_text(f.scene_file, io::write_scene(f.original)))
        s.error = *err;
      if (auto err = io::write_text(f.shrunk_file, io::write_scene(f.shrunk)))
        s.error = *err;
      if (auto err = write_path_picture(f.picture_file, f.shrunk, f.comparison))
        s.error = *err;
    }
    s.findings.push_back(std::move(f));
  }
  s.seconds = since(start);
  if (!settings.out_dir.empty()) {
    nlohmann::json j;
    j["driver"] = driver.info().name;
    j["description"] = driver.info().description;
    j["seed"] = settings.seed;
    j["cases"] = s.cases;
    j["skipped"] = s.skipped;
    j["mismatches"] = s.mismatches;
    j["alpha_tolerance"] = settings.compare.alpha_tolerance;
    j["mode"] = settings.compare.legal ? "legal" : "exact";
    j["pixels"] = s.pixels;
    j["legal_ties"] = s.legal_ties;
    j["tie_pixels"] = s.tie_pixels;
    j["boundary_conventions"] = conventions_text(s.conventions, s.tie_pixels);
    j["within_tolerance"] = s.within;
    j["max_alpha_error"] = s.max_alpha_error;
    j["seconds"] = {
        {"campaign", s.seconds}, {"driver", s.driver_seconds}, {"reference", s.reference_seconds}};
    for (std::size_t k = 0; k < kDiffClassCount; ++k) {
      const std::string name(to_string(static_cast<DiffClass>(k)));
      j["classes"][name] = {{"cases", s.cases_by_class[k]}, {"pixels", s.pixels_by_class[k]}};
    }
    for (const auto& [name, counts] : s.families)
      j["families"][name] = {{"cases", counts.first}, {"mismatches", counts.second}};
    j["findings"] = nlohmann::json::array();
    for (const PathFinding& f : s.findings) {
      nlohmann::json fj = {{"case", f.case_index},
                           {"family", f.family},
                           {"class", std::string(to_string(f.klass))},
                           {"scene", f.scene_file},
                           {"shrunk", f.shrunk_file},
                           {"picture", f.picture_file},
                           {"shrunk_scene", nlohmann::json::parse(io::write_scene(f.shrunk))}};
      fj["diffs"] = nlohmann::json::array();
      for (std::size_t k = 0; k < f.comparison.diffs.size() && k < 16; ++k)
        fj["diffs"].push_back(diff_json(f.comparison.diffs[k]));
      j["findings"].push_back(std::move(fj));
    }
    if (!s.error.empty())
      j["error"] = s.error;
    if (s.interrupted)
      j["interrupted"] = true;
    if (auto err = io::write_text(std::filesystem::path(settings.out_dir) / "report.json",
                                  j.dump(2) + "\n"))
      s.error = *err;
  }
  return s;
}

// rule: FUZZ.PATH.REPORT
void print_path_summary(std::FILE* out, const PathSettings& settings,
                        const driver::DriverInfo& info, const PathSummary& s) {
  std::fprintf(out, "driver      %s (%s)\n", info.name.c_str(), info.description.c_str());
  std::fprintf(out, "grid        %s; aliased: %s; antialiased: %s\n", info.paths.grid.c_str(),
               info.paths.aliased_method.c_str(), info.paths.antialiased_method.c_str());
  std::fprintf(out, "cases       %llu run, %llu skipped, %llu with differences (seed %llu)\n",
               static_cast<unsigned long long>(s.cases), static_cast<unsigned long long>(s.skipped),
               static_cast<unsigned long long>(s.mismatches),
               static_cast<unsigned long long>(settings.seed));
  std::fprintf(out,
               "pixels      %llu compared; legal: %llu boundary ties, %llu alpha within %d; "
               "largest alpha error %d\n",
               static_cast<unsigned long long>(s.pixels),
               static_cast<unsigned long long>(s.legal_ties),
               static_cast<unsigned long long>(s.within), settings.compare.alpha_tolerance,
               s.max_alpha_error);
  if (info.paths.samples)
    std::fprintf(out, "boundary    %s\n", conventions_text(s.conventions, s.tie_pixels).c_str());
  for (std::size_t k = 0; k < kDiffClassCount; ++k)
    if (s.cases_by_class[k] > 0 || s.pixels_by_class[k] > 0)
      std::fprintf(out, "class       %-17s %llu cases, %llu pixels\n",
                   std::string(to_string(static_cast<DiffClass>(k))).c_str(),
                   static_cast<unsigned long long>(s.cases_by_class[k]),
                   static_cast<unsigned long long>(s.pixels_by_class[k]));
  if (s.driver_seconds > 0)
    std::fprintf(out,
                 "speed       %s %.3f s, the exact kernel %.3f s on the same scenes (exact / %s = "
                 "%.2f)\n",
                 info.name.c_str(), s.driver_seconds, s.reference_seconds, info.name.c_str(),
                 s.reference_seconds / s.driver_seconds);
  for (const PathFinding& f : s.findings) {
    std::size_t contours = 0, segments = 0;
    for (const Primitive& p : f.shrunk.primitives)
      if (p.path)
        for (const FloatContour& c : p.path->contours) {
          ++contours;
          segments += c.segments.size();
        }
    std::fprintf(out,
                 "finding     case %llu (%s): %s, shrunk to %zu contour(s), %zu segment(s)%s%s\n",
                 static_cast<unsigned long long>(f.case_index), f.family.c_str(),
                 std::string(to_string(f.klass)).c_str(), contours, segments,
                 f.shrunk_file.empty() ? "" : ": ", f.shrunk_file.c_str());
  }
  if (!s.error.empty())
    std::fprintf(out, "error       %s\n", s.error.c_str());
}

} // namespace rastrules::fuzzer::paths
