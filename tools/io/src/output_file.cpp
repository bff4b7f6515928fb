// SPDX-License-Identifier: MIT
// Output files that appear only when complete (rastrules/io/output_file.hpp).
// Implements: SCENE.INPUT.ERRORS (output files)
#include "rastrules/io/output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

#include "rastrules/io/interrupt.hpp"

namespace rastrules::io {

bool same_output_file(const std::string& a, const std::string& b) {
  std::error_code ea, eb;
  const std::filesystem::path ca = std::filesystem::weakly_canonical(a, ea);
  const std::filesystem::path cb = std::filesystem::weakly_canonical(b, eb);
  return ea || eb ? a == b : ca == cb;
}

OutputFile::~OutputFile() {
  discard();
}

void OutputFile::discard() {
  if (is_stdout_ || file_ == nullptr)
    return;
  std::fclose(file_);
  file_ = nullptr;
  if (is_in_place_)
    return;
  std::error_code ec;
  std::filesystem::remove(temp_path_, ec);
  forget_temporary(interrupt_slot_);
  interrupt_slot_ = -1;
}

namespace {

// The file a path names (a symbolic link followed: ec set when it cannot be) and whether it is
// an existing file that is not a regular one (a device or a pipe).
std::pair<std::filesystem::path, bool> real_target(const std::string& path, std::error_code& ec) {
  ec.clear();
  std::error_code status_ec; // a path that does not exist yet is not an error
  std::filesystem::path target = path;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, status_ec))) {
    target = std::filesystem::weakly_canonical(path, ec);
    if (ec)
      return {target, false};
  }
  const auto st = std::filesystem::status(target, status_ec);
  return {target, std::filesystem::exists(st) && !std::filesystem::is_regular_file(st)};
}

} // namespace

namespace {
// The writers hand stdio chunks of 64 KiB (the fragment lists' buffers); through stdio's
// default 4 KiB buffer each became two write(2) calls (61440 + 4096 bytes). A buffer as large as
// the chunks makes one call a chunk.
constexpr std::size_t kStdioBuffer = std::size_t{1} << 16;
} // namespace

// Set before the first write, as setvbuf requires (glibc ignores the size of a buffer it is to
// allocate itself, hence ours); a failure leaves the default buffer, which is only slower.
void OutputFile::use_large_buffer() {
  if (!buffer_)
    buffer_ = std::make_unique_for_overwrite<char[]>(kStdioBuffer);
  (void)std::setvbuf(file_, buffer_.get(), _IOFBF, kStdioBuffer);
}

bool OutputFile::writes_in_place(const std::string& path) {
  std::error_code ec;
  return path == "-" || real_target(path, ec).second;
}

std::optional<std::string> OutputFile::open(const std::string& path) {
  path_ = path;
  if (path == "-") {
    is_stdout_ = true;
    file_ = stdout;
    return std::nullopt;
  }
  // A symbolic link is followed: the temporary file is written beside the link's real target
  // and renamed onto it, so the link stays and an error leaves the target as it was. Devices
  // and pipes (/dev/null, /dev/stdout, a FIFO) are written in place: renaming a temporary file
  // over them would replace them.
  std::error_code ec;
  const auto [target, in_place] = real_target(path, ec);
  if (ec)
    return path + ": cannot follow the link: " + ec.message();
  if (in_place) {
    is_in_place_ = true;
    file_ = std::fopen(path.c_str(), "wb");
    if (file_ == nullptr)
      return path + ": cannot open: " + std::strerror(errno);
    use_large_buffer();
    return std::nullopt;
  }
  // The temporary's name is short (a name of NAME_MAX bytes has no room for a suffix) and
  // unique within the process (render writes several outputs at once).
  static unsigned serial = 0;
  target_path_ = target.string();
  temp_path_ = (target.parent_path() / (".rastrules-" + std::to_string(::getpid()) + "-" +
                                        std::to_string(serial++) + ".tmp"))
                   .string();
  // rule: SCENE.INPUT.ERRORS
  // Registered before it exists, so that an interrupt never leaves it behind.
  interrupt_slot_ = register_temporary(temp_path_);
  file_ = std::fopen(temp_path_.c_str(), "wb");
  if (file_ == nullptr) {
    forget_temporary(interrupt_slot_);
    interrupt_slot_ = -1;
    return path + ": cannot create: " + std::strerror(errno);
  }
  use_large_buffer();
  return std::nullopt;
}

std::optional<std::string> OutputFile::commit() {
  if (is_stdout_) {
    if (std::fflush(stdout) != 0)
      return std::string("<stdout>: write failed");
    return std::nullopt;
  }
  const bool write_failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (is_in_place_) {
    if (write_failed || close_failed)
      return path_ + ": write failed";
    return std::nullopt;
  }
  std::error_code ec;
  std::optional<std::string> failure;
  if (write_failed || close_failed) {
    std::filesystem::remove(temp_path_, ec);
    failure = path_ + ": write failed";
  } else {
    std::filesystem::rename(temp_path_, target_path_, ec);
    if (ec) {
      failure = path_ + ": cannot write: " + ec.message();
      std::filesystem::remove(temp_path_, ec);
    }
  }
  forget_temporary(interrupt_slot_);
  interrupt_slot_ = -1;
  return failure;
}

std::optional<std::string> write_text(const std::filesystem::path& path, const std::string& text) {
  OutputFile out;
  if (auto err = out.open(path.string()))
    return err;
  if (std::fwrite(text.data(), 1, text.size(), out.get()) != text.size())
    return path.string() + ": write failed";
  return out.commit();
}

} // namespace rastrules::io
