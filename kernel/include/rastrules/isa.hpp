// SPDX-License-Identifier: MIT
// Instruction sets of the fast traversal and how one is chosen at run time (FAST.ISA.DISPATCH),
// and the options every render entry point takes (traversal, instruction set, threads).
// Implements: FAST.ISA.DISPATCH, FAST.EQUALS.PLAIN (choice of traversal),
// FAST.THREADS.DETERMINISTIC

#pragma once

#include <optional>
#include <string_view>

#include "rastrules/name_table.hpp"

namespace rastrules {

// rule: FAST.ISA.DISPATCH
enum class Isa { kScalar, kAvx2, kAvx512 };
template <> struct Names<Isa> {
  static constexpr auto table = in_enum_order<Isa>({"scalar", "avx2", "avx512"});
};
[[nodiscard]] std::optional<Isa> parse_isa(std::string_view name);
// The environment variable that caps the instruction sets isa_supported() reports, to reproduce
// a smaller processor: RASTRULES_MAX_ISA=scalar|avx2|avx512 (isa_cap() reads it; unset or empty:
// no cap; an unknown value caps at scalar, and the command line rejects it with an error).
inline constexpr const char* kMaxIsaVariable = "RASTRULES_MAX_ISA";
[[nodiscard]] std::optional<Isa> isa_cap();
// Whether this build has code for isa, this processor can run it (CPUID, at run time) and
// isa_cap() allows it. Isa values are ordered scalar < avx2 < avx512.
[[nodiscard]] bool isa_supported(Isa isa);
// The widest supported instruction set: avx512 (F+BW+VL), else avx2, else scalar (decided at
// the first call).
[[nodiscard]] Isa best_isa();

// Which traversal decides coverage. Both give the same fragments in the same order
// (FAST.EQUALS.PLAIN); kPlain is the bounding-box walk of RASTER.WALK.BBOX, kept as the
// reference the fast one is compared against.
enum class Traversal { kPlain, kFast };
template <> struct Names<Traversal> {
  static constexpr auto table = in_enum_order<Traversal>({"plain", "fast"});
};
[[nodiscard]] std::optional<Traversal> parse_traversal(std::string_view name);

struct RenderOptions {
  Traversal traversal = Traversal::kFast;
  std::optional<Isa> isa; // nullopt: best_isa(); an unsupported one is a precondition violation
  unsigned threads = 1;   // >= 1; results do not depend on it (FAST.THREADS.DETERMINISTIC)
};

// Returns options.isa or best_isa().
[[nodiscard]] Isa effective_isa(const RenderOptions& options);

} // namespace rastrules
