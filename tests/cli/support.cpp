// SPDX-License-Identifier: MIT
// Helpers for the command-line tests.

#include "support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csetjmp>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

#include <png.h>

namespace rastrules::test {
namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::atomic<int> g_counter{0};

} // namespace

TempDir::TempDir() {
  const auto base = std::filesystem::temp_directory_path();
  for (;;) {
    path_ = base / ("rastrules-cli-test-" + std::to_string(::getpid()) + "-" +
                    std::to_string(g_counter++));
    std::error_code ec;
    if (std::filesystem::create_directory(path_, ec))
      break;
  }
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::filesystem::path TempDir::write(const std::string& name, const std::string& text) const {
  const auto p = path_ / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::vector<std::string> RunResult::err_lines() const {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

namespace {

RunResult run_command(std::string cmd, const std::vector<std::string>& args,
                      const std::string& stdin_path, const TempDir& io) {
  const auto out_path = io / "stdout";
  const auto err_path = io / "stderr";
  for (const std::string& a : args)
    cmd += " " + shell_quote(a);
  cmd += " <" + shell_quote(stdin_path) + " >" + shell_quote(out_path.string()) + " 2>" +
         shell_quote(err_path.string());
  const int raw = std::system(cmd.c_str());
  RunResult r;
  r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out_path);
  r.err = read_file(err_path);
  return r;
}

} // namespace

RunResult run_cli(const std::vector<std::string>& args, const std::string& stdin_path) {
  const TempDir io;
  return run_command(shell_quote(RASTRULES_CLI), args, stdin_path, io);
}

#ifdef RASTRULES_TEST_PEAK // the CLI tests (tests/cli/CMakeLists.txt) build the helper
RunResult run_cli_peak(const std::vector<std::string>& args, long& peak_kib) {
  const TempDir io;
  const auto peak_path = io / "peak";
  RunResult r = run_command(shell_quote(RASTRULES_TEST_PEAK) + " " +
                                shell_quote(peak_path.string()) + " " + shell_quote(RASTRULES_CLI),
                            args, "/dev/null", io);
  peak_kib = -1;
  std::istringstream in(read_file(peak_path));
  if (long v = 0; in >> v)
    peak_kib = v;
  return r;
}
#endif

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

RunResult explain_pixel(const std::string& pixel, const std::string& scene_json) {
  const TempDir dir;
  return run_cli({"explain", dir.write("scene.json", scene_json).string(), "--pixel", pixel});
}

RenderResult render_fragments(const std::string& scene_json) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", scene_json);
  RenderResult r{run_cli({"render", scene.string(), "--fragments", (dir / "out.json").string()}),
                 ""};
  r.fragments = read_file(dir / "out.json");
  return r;
}

namespace {

// libpng reports errors by longjmp: only trivially destructible objects live in this frame.
bool read_png_rows(std::FILE* f, Png* out, int color_type, std::size_t channels) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr)
    return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, f);
  png_read_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  const bool rgb8 =
      png_get_color_type(png, info) == color_type && png_get_bit_depth(png, info) == 8;
  if (rgb8) {
    out->width = png_get_image_width(png, info);
    out->height = png_get_image_height(png, info);
    png_bytepp rows = png_get_rows(png, info);
    out->rgb.resize(static_cast<std::size_t>(out->width) * out->height * channels);
    for (std::uint32_t y = 0; y < out->height; ++y) {
      std::copy(rows[y], rows[y] + static_cast<std::size_t>(out->width) * channels,
                out->rgb.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) *
                                                               out->width * channels));
    }
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return rgb8;
}

// Reads an 8-bit PNG of `color_type` (`channels` bytes per pixel); nullopt when the file is not
// one.
std::optional<Png> read_png_file(const std::filesystem::path& path, int color_type,
                                 std::size_t channels) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr)
    return std::nullopt;
  Png png;
  const bool ok = read_png_rows(f, &png, color_type, channels);
  std::fclose(f);
  if (!ok)
    return std::nullopt;
  return png;
}

} // namespace

std::optional<Png> read_png(const std::filesystem::path& path) {
  return read_png_file(path, PNG_COLOR_TYPE_RGB, 3);
}

std::optional<Png> read_png_rgba(const std::filesystem::path& path) {
  return read_png_file(path, PNG_COLOR_TYPE_RGB_ALPHA, 4);
}

} // namespace rastrules::test
