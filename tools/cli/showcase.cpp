// SPDX-License-Identifier: MIT
// rastrules showcase: render the built-in scenes, write their files and pictures, and
// compare every fragment list with the exact oracles (oracle/): triangles with the
// triangle oracle, points with the triangle oracle on their exact squares (or the point
// oracle), aliased lines with the line oracle, antialiased lines with the AA-line oracle
// (pixels exactly, coverage within LINE.AA.PRECISION); multisampled scenes with the exact
// multisampling oracle (oracle/msaa.hpp): every fragment field (mask, sample, helper,
// centroid, derivatives) and the resolved target.

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <tuple>
#include <variant>
#include <vector>

#include "cli.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/names.hpp"
#include "rastrules/oracle/line.hpp"
#include "rastrules/oracle/line_aa.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "showcase_scenes.hpp"

namespace rastrules::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

oracle::State oracle_state(const RasterState& st) {
  oracle::State o;
  o.cull = std::string(to_string(st.cull));
  o.front_face = std::string(to_string(st.front_face));
  o.fill = std::string(to_string(st.fill));
  return o;
}

// One primitive's fragments as the oracles see them: pixels with the segment (strips) and
// nothing else; coverage is checked separately.
using Key = std::tuple<std::int32_t, std::int32_t, std::int64_t>; // (y, x, seg or -1)
Key key_of(const Fragment& f) {
  return {f.y, f.x, f.seg ? std::int64_t{*f.seg} : -1};
}

std::string key_text(std::uint32_t prim, const Key& k) {
  return "prim " + std::to_string(prim) + " pixel (" + std::to_string(std::get<1>(k)) + ", " +
         std::to_string(std::get<0>(k)) + ")" +
         (std::get<2>(k) >= 0 ? " seg " + std::to_string(std::get<2>(k)) : std::string());
}

// The result of checking one scene against the oracles.
struct Check {
  bool same = true;
  std::vector<std::string> differences; // at most a few
  std::vector<std::string> oracles;     // which oracle checked which primitives
  void note(const std::string& d) {
    same = false;
    if (differences.size() < 10)
      differences.push_back(d);
  }
  void used(const std::string& name) {
    if (std::find(oracles.begin(), oracles.end(), name) == oracles.end())
      oracles.push_back(name);
  }
};

// Compares one primitive's kernel fragments with the oracle's sorted keys.
void compare_keys(std::uint32_t prim, const std::vector<Fragment>& kernel, std::vector<Key> exact,
                  Check& check) {
  std::sort(exact.begin(), exact.end());
  std::vector<Key> mine;
  mine.reserve(kernel.size());
  for (const Fragment& f : kernel)
    mine.push_back(key_of(f));
  std::size_t i = 0, j = 0;
  while (i < mine.size() || j < exact.size()) {
    if (j == exact.size() || (i < mine.size() && mine[i] < exact[j])) {
      check.note("only the kernel covers " + key_text(prim, mine[i++]));
    } else if (i == mine.size() || exact[j] < mine[i]) {
      check.note("only the oracle covers " + key_text(prim, exact[j++]));
    } else {
      ++i;
      ++j;
    }
  }
  for (const Fragment& f : kernel) {
    if (f.mask != 1u)
      check.note("mask " + std::to_string(f.mask) + " at " + key_text(prim, key_of(f)));
  }
}

// The raw 16.8 position of the centre of pixel (x, y) (COORD.PIXEL.CENTER).
std::array<std::int64_t, 2> centre_raw(std::int32_t x, std::int32_t y) {
  return {std::int64_t{x} * 256 + 128, std::int64_t{y} * 256 + 128};
}

// Returns raw 16.8 of a float by the oracle's own snapping (never the kernel's).
std::array<std::int64_t, 2> oracle_raw(const FloatPoint& v) {
  const auto x = oracle::snap(v[0]);
  const auto y = oracle::snap(v[1]);
  if (!x || !y)
    throw std::invalid_argument("oracle: a coordinate does not snap");
  return {*x, *y};
}

// Appends the oracle's pixels of the aliased or quadrilateral line a -> b (raw 16.8) to out.
// Returns false when no oracle exists for the mode.
// rule: SCENE.LINE_MODE
bool line_oracle(const std::array<std::int64_t, 2>& a, const std::array<std::int64_t, 2>& b,
                 LineMode mode, const Scene& scene, std::int64_t seg, std::vector<Key>& out,
                 Check& check) {
  if (mode == LineMode::kQuadWide || mode == LineMode::kQuadNarrow) {
    const std::string name(io::line_mode_name(mode));
    check.used("quad-line oracle (quad_line_covers)");
    for (std::int32_t y = 0; y < scene.height; ++y) {
      for (std::int32_t x = 0; x < scene.width; ++x) {
        if (oracle::quad_line_covers(a, b, name, centre_raw(x, y),
                                     std::string(to_string(scene.state.fill)))) {
          out.push_back(Key{y, x, seg});
        }
      }
    }
    return true;
  }
  check.used("line oracle (aliased_line_pixels)");
  const std::string name(name_of(mode));
  for (const auto& px : oracle::aliased_line_pixels(a, b, name, scene.width, scene.height)) {
    out.push_back(Key{px[1], px[0], seg});
  }
  return true;
}

// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.OUTPUT.COVERAGE
Check check_scene(const Scene& scene, const PreparedScene& ps,
                  const std::vector<Fragment>& kernel) {
  Check check;
  // The kernel's fragments per primitive.
  std::vector<std::vector<Fragment>> per_prim(scene.primitives.size());
  for (const Fragment& f : kernel)
    per_prim[f.prim].push_back(f);
  // Triangles: one oracle scene holding all triangle primitives.
  oracle::Scene tris;
  tris.width = scene.width;
  tris.height = scene.height;
  tris.state = oracle_state(scene.state);
  std::vector<std::uint32_t> tri_prim;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    if (prim.type != PrimitiveType::kTriangle)
      continue;
    tris.triangles.push_back({prim.v[0], prim.v[1], prim.v[2]});
    tri_prim.push_back(static_cast<std::uint32_t>(p));
  }
  std::vector<std::vector<Key>> exact(scene.primitives.size());
  if (!tris.triangles.empty()) {
    check.used("triangle oracle (render)");
    for (const oracle::Fragment& f : oracle::render(tris)) {
      exact[tri_prim[f.prim]].push_back(Key{f.y, f.x, -1});
    }
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    const auto id = static_cast<std::uint32_t>(p);
    switch (prim.type) {
    case PrimitiveType::kTriangle:
      break;
    case PrimitiveType::kPoint: {
      // The exact half-open square around the oracle's own snapped centre, every pixel.
      check.used("point oracle (point_covers)");
      const auto c = oracle_raw(prim.v[0]);
      if (!oracle::point_in_range(c))
        throw std::invalid_argument("oracle: point out of range");
      for (std::int32_t y = 0; y < scene.height; ++y) {
        for (std::int32_t x = 0; x < scene.width; ++x) {
          if (oracle::point_covers(c, centre_raw(x, y), std::string(to_string(scene.state.fill)))) {
            exact[p].push_back(Key{y, x, -1});
          }
        }
      }
      break;
    }
    case PrimitiveType::kLine:
    case PrimitiveType::kLineStrip: {
      const bool strip = prim.type == PrimitiveType::kLineStrip;
      for (std::size_t s = 0; s + 1 < prim.v.size(); ++s) {
        const std::int64_t seg = strip ? static_cast<std::int64_t>(s) : -1;
        const auto a = oracle_raw(prim.v[s]);
        const auto b = oracle_raw(prim.v[s + 1]);
        if (prim.aa) {
          check.used("AA-line oracle (aa_pixels, aa_check within 1/65536)");
          for (const auto& px : oracle::aa_pixels(a, b, scene.width, scene.height)) {
            exact[p].push_back(Key{px[1], px[0], seg});
          }
          for (const Fragment& f : per_prim[p]) {
            if (f.seg.value_or(0) != s)
              continue;
            const oracle::AACheck c = oracle::aa_check(a, b, f.x, f.y, f.coverage_q16.value_or(0));
            if (!c.within_bound) {
              check.note("coverage " + std::to_string(f.coverage_q16.value_or(0)) + "/65536 at " +
                         key_text(id, key_of(f)) + " is not within 1/65536 of the exact " +
                         std::to_string(c.approx));
            }
          }
        } else {
          if (!line_oracle(a, b, ps.line_mode, scene, seg, exact[p], check)) {
            check.note("no oracle for " + std::string(to_string(prim.type)) + " in line_mode " +
                       std::string(io::line_mode_name(ps.line_mode)));
          }
        }
      }
      break;
    }
    }
    compare_keys(id, per_prim[p], exact[p], check);
  }
  return check;
}

// Whether a scene goes to the multisampling oracle: anything SCENE.MSAA asks for beyond one
// sample at the centre with pixel shading.
bool multisampled(const Scene& scene) {
  const MultisampleState& ms = scene.msaa;
  return ms.count() > 1 || ms.pattern.kind != PatternKind::kStandard || ms.has_centroid ||
         ms.wants_quads() || ms.shading != ShadingRate::kPixel ||
         ms.sample_mask != MultisampleState{}.sample_mask;
}

// The scene as the multisampling oracle reads it: its own snapping, strings for every state.
oracle::msaa::Input oracle_msaa_input(const Scene& scene) {
  oracle::msaa::Input in;
  in.width = scene.width;
  in.height = scene.height;
  in.state = oracle_state(scene.state);
  in.line_mode = std::string(io::line_mode_name(scene.line_mode));
  in.pattern.clear();
  for (const SampleOffset& o : scene.msaa.pattern.positions)
    in.pattern.push_back({o.x, o.y});
  in.sample_mask = scene.msaa.sample_mask;
  if (scene.msaa.has_centroid)
    in.centroid = std::string(to_string(scene.msaa.centroid_rule));
  in.shading = std::string(to_string(scene.msaa.shading));
  in.quads = scene.msaa.quads;
  in.derivatives = std::string(to_string(scene.msaa.derivatives));
  in.clear_color = scene.clear_color;
  for (const Primitive& prim : scene.primitives) {
    oracle::msaa::Primitive op;
    op.type = std::string(to_string(prim.type));
    for (const FloatPoint& v : prim.v)
      op.v.push_back(oracle_raw(v));
    op.aa = prim.aa;
    op.color = prim.color;
    in.primitives.push_back(std::move(op));
  }
  return in;
}

std::string opt_text(const std::optional<std::uint32_t>& v) {
  return v ? std::to_string(*v) : "-";
}

// One fragment as text, the same for the kernel's and the oracle's.
std::string msaa_text(std::uint32_t prim, std::int32_t x, std::int32_t y, std::uint32_t mask,
                      const std::optional<std::uint32_t>& seg,
                      const std::optional<std::uint32_t>& sample, bool helper,
                      const std::optional<std::array<std::int64_t, 2>>& centroid,
                      const std::optional<std::array<std::int64_t, 4>>& d) {
  std::string t = "prim " + std::to_string(prim) + " pixel (" + std::to_string(x) + ", " +
                  std::to_string(y) + ") seg " + opt_text(seg) + " sample " + opt_text(sample) +
                  " mask " + std::to_string(mask) + (helper ? " helper" : "");
  if (centroid)
    t += " centroid (" + std::to_string((*centroid)[0]) + ", " + std::to_string((*centroid)[1]) +
         ")/16";
  if (d) {
    t += " ddx (" + std::to_string((*d)[0]) + ", " + std::to_string((*d)[1]) + ") ddy (" +
         std::to_string((*d)[2]) + ", " + std::to_string((*d)[3]) + ")/16";
  }
  return t;
}

// Compares a multisampled scene's fragments and resolved target with the exact oracle.
// rule: SCENE.OUTPUT.MSAA, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11
// rule: MSAA.CENTROID.D3D10, MSAA.QUAD.HELPER, MSAA.DERIV.FINE, MSAA.DERIV.COARSE
// rule: MSAA.RESOLVE.AVERAGE
Check check_msaa_scene(const Scene& scene, const PreparedScene& ps,
                       const std::vector<Fragment>& kernel) {
  Check check;
  check.used("multisampling oracle (msaa::render, msaa::resolve)");
  const oracle::msaa::Input in = oracle_msaa_input(scene);
  const std::vector<oracle::msaa::Fragment> exact = oracle::msaa::render(in);
  std::vector<std::string> mine, theirs;
  for (const Fragment& f : kernel) {
    std::optional<std::array<std::int64_t, 2>> c;
    if (f.centroid)
      c = std::array<std::int64_t, 2>{f.centroid->offset.x, f.centroid->offset.y};
    std::optional<std::array<std::int64_t, 4>> d;
    if (f.derivatives) {
      d = std::array<std::int64_t, 4>{f.derivatives->ddx_x, f.derivatives->ddx_y,
                                      f.derivatives->ddy_x, f.derivatives->ddy_y};
    }
    if (f.coverage_q16)
      check.note("a coverage on a multisampled fragment at prim " + std::to_string(f.prim));
    mine.push_back(msaa_text(f.prim, f.x, f.y, f.mask, f.seg, f.sample, f.helper, c, d));
  }
  for (const oracle::msaa::Fragment& f : exact) {
    std::optional<std::array<std::int64_t, 2>> c;
    if (f.centroid)
      c = std::array<std::int64_t, 2>{f.centroid->offset.x, f.centroid->offset.y};
    std::optional<std::array<std::int64_t, 4>> d;
    if (f.derivatives) {
      d = std::array<std::int64_t, 4>{f.derivatives->ddx_x, f.derivatives->ddx_y,
                                      f.derivatives->ddy_x, f.derivatives->ddy_y};
    }
    theirs.push_back(msaa_text(f.prim, f.x, f.y, f.mask, f.seg, f.sample, f.helper, c, d));
  }
  // The lists are in the same order (SCENE.OUTPUT.MSAA); report where they part.
  const std::size_t n = std::max(mine.size(), theirs.size());
  for (std::size_t i = 0; i < n; ++i) {
    const std::string a = i < mine.size() ? mine[i] : "(nothing)";
    const std::string b = i < theirs.size() ? theirs[i] : "(nothing)";
    if (a != b)
      check.note("fragment " + std::to_string(i) + ": kernel " + a + ", oracle " + b);
  }
  // The resolved target.
  const auto resolved = resolve(ps, kernel);
  if (const auto* err = std::get_if<SceneError>(&resolved)) {
    check.note("resolve failed: " + err->what());
    return check;
  }
  const std::vector<oracle::msaa::Rgba> exact_pixels = oracle::msaa::resolve(in, exact);
  const std::vector<Rgba8>& pixels = std::get<ResolvedImage>(resolved).pixels;
  if (pixels.size() != exact_pixels.size()) {
    check.note("resolve: " + std::to_string(pixels.size()) + " pixels, the oracle " +
               std::to_string(exact_pixels.size()));
    return check;
  }
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (pixels[i] != exact_pixels[i]) {
      check.note("resolve differs at pixel (" +
                 std::to_string(i % static_cast<std::size_t>(scene.width)) + ", " +
                 std::to_string(i / static_cast<std::size_t>(scene.width)) + ")");
    }
  }
  return check;
}

std::optional<std::string> write_text(const std::filesystem::path& path, const std::string& text) {
  OutputFile f;
  if (auto err = f.open(path.string()))
    return err;
  if (std::fwrite(text.data(), 1, text.size(), f.get()) != text.size())
    return path.string() + ": write failed";
  return f.commit();
}

std::optional<std::string> write_picture(const std::filesystem::path& path,
                                         const PreparedScene& scene,
                                         const std::vector<Fragment>& fragments) {
  io::CoverageMap coverage(scene.width, scene.height);
  const int scale = io::default_picture_scale(scene.width, scene.height);
  if (io::samples_visible(scene, scale))
    coverage.record_samples(scene.msaa.count());
  for (const Fragment& f : fragments)
    coverage.add_fragment(f);
  const io::Image image = io::draw_picture(scene, coverage, scale);
  OutputFile f;
  if (auto err = f.open(path.string()))
    return err;
  if (auto err = io::write_png(f.get(), image))
    return path.string() + ": " + *err;
  return f.commit();
}

// Writes the resolved target of a multisampled scene (MSAA.RESOLVE.AVERAGE).
std::optional<std::string> write_resolve(const std::filesystem::path& path,
                                         const PreparedScene& scene,
                                         const std::vector<Fragment>& fragments) {
  const auto resolved = resolve(scene, fragments);
  if (const auto* err = std::get_if<SceneError>(&resolved))
    return path.string() + ": " + err->what();
  const ResolvedImage& r = std::get<ResolvedImage>(resolved);
  std::vector<std::uint8_t> rgba;
  for (const Rgba8& p : r.pixels)
    rgba.insert(rgba.end(), p.begin(), p.end());
  OutputFile f;
  if (auto err = f.open(path.string()))
    return err;
  if (auto err = io::write_png_rgba(f.get(), r.width, r.height, rgba))
    return path.string() + ": " + *err;
  return f.commit();
}

} // namespace

int run_showcase(const Args& args) {
  std::optional<std::string> out_dir;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      print_usage(stdout);
      return kExitOk;
    } else if (a == "--out" && i + 1 < args.size()) {
      out_dir = args[++i];
    } else if (a.rfind("--out=", 0) == 0) {
      out_dir = a.substr(6);
    } else if (a == "--out") {
      return usage_error("--out needs a directory");
    } else {
      return usage_error("showcase: unexpected argument \"" + a + "\"");
    }
  }
  if (!out_dir || out_dir->empty())
    return usage_error("showcase: missing --out DIR");
  const std::filesystem::path dir(*out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    return error(*out_dir + ": cannot create the directory" +
                 (ec ? ": " + ec.message() : std::string()));
  }

  const std::vector<ShowcaseScene> scenes = showcase_scenes();
  std::printf("%-22s %6s %9s %10s %10s  %s\n", "scene", "prims", "fragments", "kernel ms",
              "oracle ms", "agree");
  int agree = 0;
  std::vector<std::string> notes;
  std::vector<std::string> checked_by_lines;
  for (const ShowcaseScene& sc : scenes) {
    const Clock::time_point k0 = Clock::now();
    auto prepared = prepare(sc.scene);
    if (auto* err = std::get_if<SceneError>(&prepared)) {
      return error("internal error: showcase scene " + sc.name + ": " + err->what());
    }
    const PreparedScene& ps = std::get<PreparedScene>(prepared);
    const std::vector<Fragment> kernel = rasterize(ps);
    const double kernel_ms = ms_since(k0);

    Check check;
    const Clock::time_point o0 = Clock::now();
    try {
      check = multisampled(sc.scene) ? check_msaa_scene(sc.scene, ps, kernel)
                                     : check_scene(sc.scene, ps, kernel);
    } catch (const std::exception& e) {
      check.note(std::string("the oracle failed: ") + e.what());
    }
    const double oracle_ms = ms_since(o0);
    bool same = check.same;
    for (const std::string& d : check.differences)
      notes.push_back(sc.name + ": " + d);
    std::string checked_by;
    for (const std::string& o : check.oracles)
      checked_by += (checked_by.empty() ? "" : ", ") + o;
    checked_by_lines.push_back(sc.name + ": " + (checked_by.empty() ? "no primitive" : checked_by));

    // The scene file must read back to exactly this scene (SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32).
    const std::string scene_text = io::write_scene(sc.scene);
    const auto reread = io::read_scene(scene_text);
    if (!std::holds_alternative<Scene>(reread) ||
        !io::same_scene(std::get<Scene>(reread), sc.scene)) {
      same = false;
      notes.push_back(sc.name + ": the written scene file does not read back to the same scene");
    }
    for (const auto& err :
         {write_text(dir / (sc.name + ".scene.json"), scene_text),
          write_text(dir / (sc.name + ".fragments.json"), io::fragments_to_json(kernel)),
          write_picture(dir / (sc.name + ".png"), ps, kernel)}) {
      if (err)
        return error(*err);
    }
    if (multisampled(sc.scene)) {
      if (auto err = write_resolve(dir / (sc.name + ".resolve.png"), ps, kernel))
        return error(*err);
    }
    if (same)
      ++agree;
    std::printf("%-22s %6zu %9zu %10.3f %10.3f  %s\n", sc.name.c_str(), sc.scene.primitives.size(),
                kernel.size(), kernel_ms, oracle_ms, same ? "yes" : "NO");
  }
  for (const std::string& n : notes)
    std::printf("  %s\n", n.c_str());
  std::printf("oracles used:\n");
  for (const std::string& n : checked_by_lines)
    std::printf("  %s\n", n.c_str());
  const int differ = static_cast<int>(scenes.size()) - agree;
  std::printf("showcase: %zu scenes, %d agree with the oracle, %d differ; pictures in %s\n",
              scenes.size(), agree, differ, dir.string().c_str());
  std::fflush(stdout);
  return differ == 0 ? kExitOk : kExitDifference;
}

} // namespace rastrules::cli
