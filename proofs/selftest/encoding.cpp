// SPDX-License-Identifier: MIT
// Self-check of the overflow encoding every proof rests on (support/sym.hpp): for each
// operation Sym performs, the recorded obligation "fits <type>" holds exactly when C++'s exact
// result fits the type, and the symbolic value and comparisons equal C++'s. Checked
// exhaustively on int8_t (all 65536 operand pairs for + - * and unary -; the six comparisons on
// a grid including both ends) and on
// int64_t and __int128 for operands at and around the type's limits, against the compiler's
// __builtin_*_overflow (and __int128's narrowing to int64_t). (Z3 4.8.12's own bit-vector
// no-overflow predicate gets constant products wrong, proofs-notes pitfall 1; this encoding does
// not use it.) Cites no rule: it is evidence about the proofs' encoding, not about the kernel.
// Assumes: (none)
// Expected: every case agrees; exit status 0 iff so.

#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {
namespace {

// Returns whether the last obligation recorded in dom simplifies to true.
bool last_obligation_holds(const Domain& dom) {
  const std::vector<Obligation> all = dom.obligations_since(dom.mark() - 1);
  return all.back().holds.simplify().is_true();
}

bool equals_int64(const z3::expr& e, std::int64_t v) {
  std::int64_t got = 0;
  const z3::expr s = e.simplify();
  return s.is_numeral_i64(got) && got == v;
}

int check_int8() {
  int failures = 0;
  auto fail = [&](const std::string& what) {
    if (failures < 10)
      std::cout << "    mismatch: " << what << "\n";
    ++failures;
  };
  using S = Sym<std::int8_t>;
  constexpr int kMin = std::numeric_limits<std::int8_t>::min();
  constexpr int kMax = std::numeric_limits<std::int8_t>::max();
  for (int a = kMin; a <= kMax; ++a) {
    Domain dom; // one per row keeps the obligation log short
    const S x(a);
    {
      const int exact = -a;
      const S r = -x;
      if (last_obligation_holds(dom) != (exact >= kMin && exact <= kMax) ||
          !equals_int64(r.expr(), exact)) {
        fail("-(" + std::to_string(a) + ")");
      }
    }
    for (int b = kMin; b <= kMax; ++b) {
      const S y(b);
      const int sums[3] = {a + b, a - b, a * b};
      const char* names[3] = {" + ", " - ", " * "};
      for (int op = 0; op < 3; ++op) {
        const S r = op == 0 ? x + y : op == 1 ? x - y : x * y;
        const bool fits = sums[op] >= kMin && sums[op] <= kMax;
        if (last_obligation_holds(dom) != fits || !equals_int64(r.expr(), sums[op])) {
          fail(std::to_string(a) + names[op] + std::to_string(b));
        }
      }
      // Comparisons create no obligation; a sparser grid (every 7th value and both ends)
      // catches a swapped or off-by-one relation.
      if (!((a - kMin) % 7 == 0 || a == kMax) || !((b - kMin) % 7 == 0 || b == kMax))
        continue;
      const bool cmp_ok = (x == y).expr().simplify().is_true() == (a == b) &&
                          (x != y).expr().simplify().is_true() == (a != b) &&
                          (x < y).expr().simplify().is_true() == (a < b) &&
                          (x <= y).expr().simplify().is_true() == (a <= b) &&
                          (x > y).expr().simplify().is_true() == (a > b) &&
                          (x >= y).expr().simplify().is_true() == (a >= b);
      if (!cmp_ok)
        fail("comparison of " + std::to_string(a) + " and " + std::to_string(b));
    }
  }
  return failures;
}

int check_int64(Domain& dom) {
  using S = Sym<std::int64_t>;
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  const std::vector<std::int64_t> values = {kMin,
                                            kMin + 1,
                                            -(std::int64_t{1} << 32),
                                            -(std::int64_t{1} << 31) - 1,
                                            -3037000500,
                                            -3037000499,
                                            -2,
                                            -1,
                                            0,
                                            1,
                                            2,
                                            3037000499,
                                            3037000500,
                                            std::int64_t{1} << 31,
                                            std::int64_t{1} << 32,
                                            kMax - 1,
                                            kMax};
  int failures = 0;
  for (const std::int64_t a : values) {
    const S x(a);
    for (const std::int64_t b : values) {
      const S y(b);
      std::int64_t out = 0;
      const bool overflow[3] = {__builtin_add_overflow(a, b, &out),
                                __builtin_sub_overflow(a, b, &out),
                                __builtin_mul_overflow(a, b, &out)};
      const char* names[3] = {" + ", " - ", " * "};
      for (int op = 0; op < 3; ++op) {
        (void)(op == 0 ? x + y : op == 1 ? x - y : x * y);
        if (last_obligation_holds(dom) == overflow[op]) {
          if (failures < 10) {
            std::cout << "    mismatch: " << a << names[op] << b << " (C++ overflow "
                      << overflow[op] << ")\n";
          }
          ++failures;
        }
      }
    }
    (void)(-x);
    if (last_obligation_holds(dom) != (a != kMin))
      ++failures;
  }
  return failures;
}

// The same for __int128 (Int128, PATH.CURVE.SAMPLE's wide products): + - * and unary - at and
// around its limits against __builtin_*_overflow, and the narrowing to int64_t.
int check_int128(Domain& dom) {
  using S = Sym<Int128>;
  const Int128 k63 = Int128{1} << 63;
  const Int128 root = Int128{1} << 63; // about sqrt(2^127) / 1.41: products near the limit
  const std::vector<Int128> values = {kInt128Min,
                                      kInt128Min + 1,
                                      -(Int128{1} << 64),
                                      -k63 - 1,
                                      -k63,
                                      -root * 2 + 1,
                                      -2,
                                      -1,
                                      0,
                                      1,
                                      2,
                                      k63 - 1,
                                      k63,
                                      root * 2 - 1,
                                      root * 2,
                                      Int128{1} << 64,
                                      kInt128Max - 1,
                                      kInt128Max};
  int failures = 0;
  for (const Int128 a : values) {
    const S x(dom, int128_val(dom.ctx(), a), "a");
    for (const Int128 b : values) {
      const S y(dom, int128_val(dom.ctx(), b), "b");
      Int128 out = 0;
      const bool overflow[3] = {__builtin_add_overflow(a, b, &out),
                                __builtin_sub_overflow(a, b, &out),
                                __builtin_mul_overflow(a, b, &out)};
      for (int op = 0; op < 3; ++op) {
        (void)(op == 0 ? x + y : op == 1 ? x - y : x * y);
        if (last_obligation_holds(dom) == overflow[op])
          ++failures;
      }
    }
    (void)(-x);
    if (last_obligation_holds(dom) != (a != kInt128Min))
      ++failures;
    (void)Sym<std::int64_t>(x); // static_cast<std::int64_t>: fits iff in int64_t's range
    if (last_obligation_holds(dom) != (a >= std::numeric_limits<std::int64_t>::min() &&
                                       a <= std::numeric_limits<std::int64_t>::max()))
      ++failures;
  }
  if (failures > 0)
    std::cout << "    __int128: " << failures << " mismatches\n";
  return failures;
}

} // namespace
} // namespace rastrules::proofs

int main() {
  using namespace rastrules::proofs;
  std::cout << "self-check of the Sym overflow encoding\n  solver: " << solver_version() << "\n";
  int failed = 0;
  {
    const int f = check_int8();
    std::cout << (f == 0 ? "AGREES" : "DISAGREES")
              << " int8_t: every + - * and unary - obligation and value, comparisons, vs C++ (" << f
              << " mismatches)\n";
    failed += f != 0;
  }
  {
    Domain dom;
    const int f = check_int64(dom);
    std::cout << (f == 0 ? "AGREES" : "DISAGREES")
              << " int64_t: + - * and unary - obligations at the limits vs __builtin_*_overflow ("
              << f << " mismatches)\n";
    failed += f != 0;
  }
  {
    Domain dom;
    const int f = check_int128(dom);
    std::cout << (f == 0 ? "AGREES" : "DISAGREES")
              << " __int128: + - * and unary - obligations at the limits vs __builtin_*_overflow, "
                 "narrowing to int64_t ("
              << f << " mismatches)\n";
    failed += f != 0;
  }
  std::cout << (3 - failed) << " passed, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}
