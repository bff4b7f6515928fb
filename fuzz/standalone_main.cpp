// SPDX-License-Identifier: MIT
// A main for fuzz targets built without a fuzzing engine (gcc, or clang without
// -fsanitize=fuzzer): runs LLVMFuzzerTestOneInput once on every file named on the command line
// and on every regular file inside every directory named, in sorted order. A crash, an abort
// or a sanitizer report fails the run; otherwise it prints how many inputs ran and exits 0.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool run_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "%s: cannot open\n", path.string().c_str());
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  // A copy in a buffer of exactly the input's size, so that ASan sees reads past its end.
  std::vector<std::uint8_t> data(bytes.begin(), bytes.end());
  (void)LLVMFuzzerTestOneInput(data.empty() ? nullptr : data.data(), data.size());
  return true;
}

} // namespace

int main(int argc, char** argv) {
  std::size_t ran = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (!arg.empty() && arg[0] == '-')
      continue; // libFuzzer flags are ignored
    const std::filesystem::path p(arg);
    std::error_code ec;
    if (std::filesystem::is_directory(p, ec)) {
      std::vector<std::filesystem::path> files;
      for (const auto& e : std::filesystem::directory_iterator(p, ec)) {
        if (e.is_regular_file())
          files.push_back(e.path());
      }
      std::sort(files.begin(), files.end());
      for (const auto& f : files) {
        if (!run_file(f))
          return 2;
        ++ran;
      }
    } else {
      if (!run_file(p))
        return 2;
      ++ran;
    }
  }
  std::printf("%s: %zu inputs ran without a failure\n", argc > 0 ? argv[0] : "fuzz", ran);
  return 0;
}
