// SPDX-License-Identifier: MIT
// Internal to the fuzzer: reading a JSON file with a size limit, and the fields that say which
// campaign a report or summary describes.

#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer::detail {

// Reads the JSON object in `path` (at most max_bytes), or sets *error ("PATH: PROBLEM").
inline std::optional<nlohmann::json> read_json_object(const std::string& path,
                                                      std::size_t max_bytes, std::string* error) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) {
    *error = path + ": cannot read";
    return std::nullopt;
  }
  if (size > max_bytes) {
    *error = path + ": larger than " + std::to_string(max_bytes >> 20) + " MiB";
    return std::nullopt;
  }
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    *error = path + ": not a JSON object";
    return std::nullopt;
  }
  return j;
}

// The campaign a report or summary describes (FUZZ.REPORT, FUZZ.SHARD).
inline nlohmann::json campaign_json(const Settings& st, const std::string& description) {
  nlohmann::json j = {{"driver", st.driver_name},
                      {"description", description},
                      {"profile", std::string(to_string(st.profile))},
                      {"mode", std::string(to_string(st.mode))},
                      {"seed", st.seed},
                      {"campaign_cases", st.cases},
                      {"shard", {{"index", st.shard_index}, {"count", st.shard_count}}}};
  if (!st.families.empty()) // FUZZ.FAMILIES: listed only when selected
    j["families_selected"] = st.families;
  return j;
}

} // namespace rastrules::fuzzer::detail
