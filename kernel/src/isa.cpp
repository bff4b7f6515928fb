// SPDX-License-Identifier: MIT
// Run-time choice of the fast traversal's instruction set (FAST.ISA.DISPATCH).

#include "rastrules/isa.hpp"

#include <cstdlib>

namespace rastrules {

std::optional<Isa> parse_isa(std::string_view name) {
  return from_name<Isa>(name);
}

std::optional<Isa> isa_cap() {
  const char* value = std::getenv(kMaxIsaVariable);
  if (value == nullptr || *value == '\0')
    return std::nullopt;
  return parse_isa(value).value_or(Isa::kScalar);
}

// rule: FAST.ISA.DISPATCH
bool isa_supported(Isa isa) {
  if (const std::optional<Isa> cap = isa_cap();
      cap && static_cast<int>(isa) > static_cast<int>(*cap))
    return false;
  switch (isa) {
  case Isa::kScalar:
    return true;
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  case Isa::kAvx2:
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  case Isa::kAvx512:
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512bw") != 0 &&
           __builtin_cpu_supports("avx512vl") != 0;
#else
  case Isa::kAvx2:
  case Isa::kAvx512:
    return false;
#endif
  }
  return false;
}

// rule: FAST.ISA.DISPATCH
Isa best_isa() {
  static const Isa best = isa_supported(Isa::kAvx512) ? Isa::kAvx512
                          : isa_supported(Isa::kAvx2) ? Isa::kAvx2
                                                      : Isa::kScalar;
  return best;
}

Isa effective_isa(const RenderOptions& options) {
  return options.isa ? *options.isa : best_isa();
}

std::optional<Traversal> parse_traversal(std::string_view name) {
  return from_name<Traversal>(name);
}

} // namespace rastrules
