// SPDX-License-Identifier: MIT
// Output files that appear only when complete: written under a temporary name beside the real
// target and renamed into place, removed on error and on an interrupt (SCENE.INPUT.ERRORS: a
// failed run leaves no damaged output file). The command line's outputs and the fuzzer's
// reports and pictures are written through them.
// Implements: SCENE.INPUT.ERRORS (output files)
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace rastrules::io {

// An output file written under a temporary name and renamed into place by commit(), so that
// a failed run leaves no output file; "-" writes to standard output; an existing path that is
// not a regular file (a device such as /dev/null, a pipe, a symbolic link) is written in place.
class OutputFile {
public:
  OutputFile() = default;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();

  // Opens the temporary file. Returns an error message on failure.
  std::optional<std::string> open(const std::string& path);
  [[nodiscard]] std::FILE* get() const { return file_; }
  // Whether open(path) writes in place (standard output, or an existing path that is not a
  // regular file): what is written there cannot be taken back, while a temporary file is
  // removed unless committed.
  [[nodiscard]] static bool writes_in_place(const std::string& path);
  // Closes the file and moves it into place. Returns an error message on failure (and then
  // removes the temporary file).
  std::optional<std::string> commit();

private:
  void discard();
  void use_large_buffer();
  std::string path_;
  std::string temp_path_;
  std::string target_path_; // path_, or the real file a link at path_ names
  int interrupt_slot_ = -1; // the temporary's slot in io::register_temporary
  std::FILE* file_ = nullptr;
  bool is_stdout_ = false;
  bool is_in_place_ = false;       // not a regular file: written directly, never renamed
  std::unique_ptr<char[]> buffer_; // file_'s stdio buffer (freed after file_ is closed)
};

// Whether two output paths name one file: equal canonical paths, following links, for files
// that exist or not (then their folders' canonical paths and the names).
[[nodiscard]] bool same_output_file(const std::string& a, const std::string& b);

// Writes `text` to `path` through an OutputFile: the file appears only when complete. Returns
// an error message on failure.
std::optional<std::string> write_text(const std::filesystem::path& path, const std::string& text);

} // namespace rastrules::io
