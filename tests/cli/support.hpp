// SPDX-License-Identifier: MIT
// Helpers for the command-line tests: temporary directories, running the rastrules binary,
// reading files and PNGs back.

#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rastrules::test {

// A fresh directory under the system temporary directory, removed with its contents on
// destruction.
class TempDir {
public:
  TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir();
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  // Writes `text` to the file `name` in the directory and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const {
    return path_ / name;
  }

private:
  std::filesystem::path path_;
};

struct RunResult {
  int status = -1; // exit status, or -1 when the process did not exit normally
  std::string out;
  std::string err;
  [[nodiscard]] std::vector<std::string> err_lines() const;
};

// Runs the rastrules binary with `args` (no shell interpretation of the arguments), with
// standard input from `stdin_path` (or /dev/null).
RunResult run_cli(const std::vector<std::string>& args,
                  const std::string& stdin_path = "/dev/null");

// The same, with the peak resident set of that run alone in KiB (its own ru_maxrss, through
// the small program rastrules_test_peak: a test process's getrusage(RUSAGE_CHILDREN) counts
// its own size at every fork), or -1 when it could not be measured. Only where the helper is
// built (the CLI tests): elsewhere a call does not compile, rather than failing to link.
#ifdef RASTRULES_TEST_PEAK
RunResult run_cli_peak(const std::vector<std::string>& args, long& peak_kib);
#endif

std::string read_file(const std::filesystem::path& path);

// Writes `scene_json` to a fresh temporary directory and runs
// `rastrules explain SCENE.json --pixel PIXEL` on it.
RunResult explain_pixel(const std::string& pixel, const std::string& scene_json);

// A run of `rastrules render SCENE.json --fragments OUT.json` and the text of OUT.json ("" when
// it was not written).
struct RenderResult : RunResult {
  std::string fragments;
};

// Writes `scene_json` to a fresh temporary directory and renders its fragment list there.
RenderResult render_fragments(const std::string& scene_json);

struct Png {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgb; // 3 bytes per pixel, rows top first
  [[nodiscard]] std::array<std::uint8_t, 3> at(std::uint32_t x, std::uint32_t y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  // For read_png_rgba().
  [[nodiscard]] std::array<std::uint8_t, 4> rgba_at(std::uint32_t x, std::uint32_t y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
    return {rgb[i], rgb[i + 1], rgb[i + 2], rgb[i + 3]};
  }
};

// Reads an 8-bit RGB PNG with libpng; nullopt when the file is not one.
std::optional<Png> read_png(const std::filesystem::path& path);

// Reads an 8-bit RGBA PNG (the resolved target); rgb then holds 4 bytes per pixel (use
// rgba_at); nullopt when the file is not one.
std::optional<Png> read_png_rgba(const std::filesystem::path& path);

} // namespace rastrules::test
