// SPDX-License-Identifier: MIT
// A symbolic IEEE-754 number type for instantiating floating-point formula templates with Z3
// terms (Z3's floating-point theory: exact IEEE-754 semantics, NaN, infinities, signed zeros
// and subnormals included).
//
// SymFloat<T> models a value of the C++ type T (float or double) as the kernel computes it:
// every + - * / rounds to nearest, ties to even (the C++ default rounding mode), one operation
// at a time (the kernel is compiled with -ffp-contract=off, so no fused multiply-add), and a
// literal `Real(0.5)` is the C++ conversion of the literal to T. Comparisons are IEEE
// comparisons (false when either side is NaN) and return SymBool. Queries over SymFloat terms
// need Solver::kFloatingPoint (support/prover.hpp).

#pragma once

#include <z3++.h>

#include <concepts>
#include <string>
#include <utility>

#include "support/sym.hpp"

namespace rastrules::proofs {

// The Z3 format (exponent bits, significand bits including the hidden bit) of T.
template <std::floating_point T> struct FloatFormat;
template <> struct FloatFormat<float> {
  static constexpr unsigned kEbits = 8;
  static constexpr unsigned kSbits = 24;
  static constexpr const char* kName = "float";
};
template <> struct FloatFormat<double> {
  static constexpr unsigned kEbits = 11;
  static constexpr unsigned kSbits = 53;
  static constexpr const char* kName = "double";
};

template <std::floating_point T> class SymFloat {
public:
  using value_type = T;

  // A literal, as C++ converts it to T (for example the `Real(0.5)` of a formula template).
  explicit SymFloat(double literal) : e_(Domain::active().ctx().fpa_val(static_cast<T>(literal))) {}
  explicit SymFloat(z3::expr e) : e_(std::move(e)) {}

  // A fresh variable of the domain, ranging over every value of T (NaN and infinities too).
  static SymFloat var(Domain& dom, const std::string& name) {
    return SymFloat(dom.fp_var(name, FloatFormat<T>::kEbits, FloatFormat<T>::kSbits));
  }

  [[nodiscard]] const z3::expr& expr() const { return e_; }

  friend SymFloat operator+(const SymFloat& a, const SymFloat& b) { return a.op(Z3_mk_fpa_add, b); }
  friend SymFloat operator-(const SymFloat& a, const SymFloat& b) { return a.op(Z3_mk_fpa_sub, b); }
  friend SymFloat operator*(const SymFloat& a, const SymFloat& b) { return a.op(Z3_mk_fpa_mul, b); }
  friend SymFloat operator/(const SymFloat& a, const SymFloat& b) { return a.op(Z3_mk_fpa_div, b); }

  friend SymBool operator<(const SymFloat& a, const SymFloat& b) { return a.cmp(Z3_mk_fpa_lt, b); }
  friend SymBool operator<=(const SymFloat& a, const SymFloat& b) {
    return a.cmp(Z3_mk_fpa_leq, b);
  }
  friend SymBool operator>(const SymFloat& a, const SymFloat& b) { return a.cmp(Z3_mk_fpa_gt, b); }
  friend SymBool operator>=(const SymFloat& a, const SymFloat& b) {
    return a.cmp(Z3_mk_fpa_geq, b);
  }
  // IEEE equality: +0 == -0, NaN != NaN (not Z3's structural `==`).
  friend SymBool operator==(const SymFloat& a, const SymFloat& b) { return a.cmp(Z3_mk_fpa_eq, b); }

private:
  using Binary = Z3_ast (*)(Z3_context, Z3_ast, Z3_ast, Z3_ast);
  using Compare = Z3_ast (*)(Z3_context, Z3_ast, Z3_ast);

  SymFloat op(Binary f, const SymFloat& b) const {
    z3::context& ctx = e_.ctx();
    const z3::expr rne(ctx, Z3_mk_fpa_rne(ctx));
    z3::expr r(ctx, f(ctx, rne, e_, b.e_));
    ctx.check_error();
    return SymFloat(r);
  }
  SymBool cmp(Compare f, const SymFloat& b) const {
    z3::context& ctx = e_.ctx();
    z3::expr r(ctx, f(ctx, e_, b.e_));
    ctx.check_error();
    return SymBool(r);
  }

  z3::expr e_;
};

// Returns std::floor(x): the IEEE roundToIntegral towards negative infinity (exact; NaN and
// infinities map to themselves, as std::floor's do).
template <std::floating_point T> SymFloat<T> floor(const SymFloat<T>& x) {
  z3::context& ctx = x.expr().ctx();
  const z3::expr rtn(ctx, Z3_mk_fpa_rtn(ctx));
  return SymFloat<T>(z3::expr(ctx, Z3_mk_fpa_round_to_integral(ctx, rtn, x.expr())));
}

// Returns static_cast<To>(x) between floating-point types: exact when widening, rounded to
// nearest even when narrowing.
template <std::floating_point To, std::floating_point From>
SymFloat<To> convert(const SymFloat<From>& x) {
  z3::context& ctx = x.expr().ctx();
  const z3::expr rne(ctx, Z3_mk_fpa_rne(ctx));
  const z3::sort s = ctx.fpa_sort(FloatFormat<To>::kEbits, FloatFormat<To>::kSbits);
  return SymFloat<To>(z3::expr(ctx, Z3_mk_fpa_to_fp_float(ctx, rne, x.expr(), s)));
}

// Returns whether x is NaN.
template <std::floating_point T> SymBool is_nan(const SymFloat<T>& x) {
  z3::context& ctx = x.expr().ctx();
  return SymBool(z3::expr(ctx, Z3_mk_fpa_is_nan(ctx, x.expr())));
}

} // namespace rastrules::proofs
