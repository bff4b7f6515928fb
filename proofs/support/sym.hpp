// SPDX-License-Identifier: MIT
// A symbolic number domain for instantiating rastrules::formula templates with Z3 terms.
//
// Sym<Rep> models a value of the C++ signed integer type Rep. It carries an exact, unbounded
// Z3 integer term, and every + - * (and unary -) it performs records the obligation "the exact
// result fits in Rep" in its Domain. Instantiating a formula template with Sym<std::int64_t>
// therefore yields both the mathematical value of the formula and the list of conditions under
// which the kernel's std::int64_t evaluation equals it (no overflow, so no wrap and no UB).
// This is sound for formula/ because it uses no division, modulo, shifts or masks: with no
// overflow, two's-complement + - * agree with integer arithmetic.
// Comparisons return SymBool, which supports && || ! so that the branch-free formula code
// compiles unchanged.

#pragma once

#include <z3++.h>

#include <concepts>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rastrules::proofs {

// The C++ type __int128 (a GCC and Clang extension, which the kernel uses for wide products:
// PATH.CURVE.SAMPLE). Under -std=c++20 without extensions std::signed_integral does not hold
// for it, so Sym's representation types are named by SymRep.
__extension__ typedef __int128 Int128;

// The limits of Int128, -2^127 and 2^127 - 1.
inline constexpr Int128 kInt128Max = ((Int128{1} << 126) - 1) + (Int128{1} << 126);
inline constexpr Int128 kInt128Min = -kInt128Max - 1;

// The types Sym can model: the standard signed integer types and Int128.
template <class T>
concept SymRep = std::signed_integral<T> || std::same_as<T, Int128>;

// Returns the Z3 integer numeral of v (beyond int64_t as decimal text).
inline z3::expr int128_val(z3::context& ctx, Int128 v) {
  if (v >= std::numeric_limits<std::int64_t>::min() &&
      v <= std::numeric_limits<std::int64_t>::max())
    return ctx.int_val(static_cast<std::int64_t>(v));
  std::string digits;
  for (Int128 u = v; u != 0; u /= 10) { // % and / truncate: digits of negative u are <= 0
    const int d = static_cast<int>(u % 10);
    digits.insert(digits.begin(), static_cast<char>('0' + (d < 0 ? -d : d)));
  }
  return ctx.int_val((v < 0 ? "-" + digits : digits).c_str());
}

// How a value is displayed in a counterexample.
enum class Unit {
  kCoordRaw, // raw 16.8 position: also shown in pixels (raw / 2^kSubpixelBits)
  kEdgeRaw,  // raw 32.16 edge value: also shown in pixel^2 (raw / 2^(2 kSubpixelBits))
  kInteger,  // a plain integer
  kBool,     // a Boolean
  kFloat,    // an IEEE-754 floating-point term: shown as a decimal and a hexadecimal float
};

// A condition the modelled C++ evaluation needs (for example "this product fits int64_t").
struct Obligation {
  std::string what; // for example "((bx - ax) * (py - ay)) fits int64_t"
  z3::expr value;   // the exact value that must fit
  z3::expr holds;   // min(Rep) <= value <= max(Rep)
};

// A named term shown in counterexamples.
struct Watch {
  std::string name;
  z3::expr value;
  Unit unit;
};

template <SymRep Rep> class Sym;

// Returns the name of the C++ type Rep models, for reports.
template <SymRep Rep> constexpr const char* type_name() {
  if constexpr (sizeof(Rep) == 1)
    return "int8_t";
  else if constexpr (sizeof(Rep) == 2)
    return "int16_t";
  else if constexpr (sizeof(Rep) == 4)
    return "int32_t";
  else if constexpr (sizeof(Rep) == 8)
    return "int64_t";
  else
    return "__int128";
}

// Owns the Z3 context, the obligation log and the variables of one proof run. Exactly one
// Domain is active at a time (the most recently constructed live one); Sym's literal
// constructor uses it, which is what lets `Num(0)` in formula templates work.
class Domain {
public:
  Domain() : previous_(active_) { active_ = this; }
  ~Domain() { active_ = previous_; }
  Domain(const Domain&) = delete;
  Domain& operator=(const Domain&) = delete;

  [[nodiscard]] static Domain& active() {
    if (active_ == nullptr)
      throw std::logic_error("no active proofs::Domain");
    return *active_;
  }
  [[nodiscard]] z3::context& ctx() { return ctx_; }

  // Returns a fresh integer variable (names must be unique within the Domain) modelling a value of
  // type Rep (its range is NOT assumed; theorems state their input ranges as explicit hypotheses).
  template <SymRep Rep> Sym<Rep> var(const std::string& name, Unit unit);

  // Returns a fresh Boolean variable.
  z3::expr bool_var(const std::string& name) {
    z3::expr v = ctx_.bool_const(name.c_str());
    dom_register(name, v, Unit::kBool);
    return v;
  }

  // Returns a fresh IEEE-754 floating-point variable with ebits exponent and sbits significand
  // bits (11, 53: double; 8, 24: float). It ranges over every value of the format, NaN and
  // infinities included; theorems state their input ranges as explicit hypotheses.
  z3::expr fp_var(const std::string& name, unsigned ebits, unsigned sbits) {
    z3::expr v = ctx_.fpa_const(name.c_str(), ebits, sbits);
    dom_register(name, v, Unit::kFloat);
    return v;
  }

  // Records that the exact value e must fit Rep for the modelled C++ evaluation to be exact.
  template <SymRep Rep> void require_fits(const z3::expr& e, const std::string& text) {
    z3::expr lo = ctx_.int_val(0);
    z3::expr hi = ctx_.int_val(0);
    if constexpr (std::same_as<Rep, Int128>) {
      // -2^127 and 2^127 - 1 (std::numeric_limits is not specialised for it without extensions).
      lo = int128_val(ctx_, kInt128Min);
      hi = int128_val(ctx_, kInt128Max);
    } else {
      lo = ctx_.int_val(static_cast<std::int64_t>(std::numeric_limits<Rep>::min()));
      hi = ctx_.int_val(static_cast<std::int64_t>(std::numeric_limits<Rep>::max()));
    }
    log_.push_back(Obligation{text + " fits " + type_name<Rep>(), e, lo <= e && e <= hi});
  }

  // The obligation log is append-only; a mark lets a theorem take what one computation added.
  [[nodiscard]] std::size_t mark() const { return log_.size(); }
  [[nodiscard]] std::vector<Obligation> obligations_since(std::size_t mark) const {
    return {log_.begin() + static_cast<std::ptrdiff_t>(mark), log_.end()};
  }

  [[nodiscard]] const std::vector<Watch>& variables() const { return variables_; }

private:
  // Variables with the same name would be the same Z3 constant, silently identifying two
  // quantities of a theorem: refuse.
  void dom_register(const std::string& name, const z3::expr& v, Unit unit) {
    for (const Watch& w : variables_) {
      if (w.name == name)
        throw std::logic_error("proof variable declared twice: " + name);
    }
    variables_.push_back(Watch{name, v, unit});
  }

  z3::context ctx_;
  std::vector<Obligation> log_;
  std::vector<Watch> variables_;
  Domain* previous_;
  static inline thread_local Domain* active_ = nullptr;
};

// A symbolic Boolean: the result of comparing Sym values.
class SymBool {
public:
  explicit SymBool(z3::expr e) : e_(std::move(e)) {}
  // A constant, in the active Domain.
  explicit SymBool(bool b) : e_(Domain::active().ctx().bool_val(b)) {}

  [[nodiscard]] const z3::expr& expr() const { return e_; }

  friend SymBool operator&&(const SymBool& a, const SymBool& b) { return SymBool(a.e_ && b.e_); }
  friend SymBool operator||(const SymBool& a, const SymBool& b) { return SymBool(a.e_ || b.e_); }
  friend SymBool operator!(const SymBool& a) { return SymBool(!a.e_); }
  friend SymBool operator==(const SymBool& a, const SymBool& b) { return SymBool(a.e_ == b.e_); }
  friend SymBool operator!=(const SymBool& a, const SymBool& b) { return SymBool(a.e_ != b.e_); }

private:
  z3::expr e_;
};

// The six comparisons of a numeric term type T (one with expr()), as the SymBool of Z3's
// comparison of the two terms. Sym and line/'s RealNum derive from it.
template <class T> struct TermComparisons {
  friend SymBool operator==(const T& a, const T& b) { return SymBool(a.expr() == b.expr()); }
  friend SymBool operator!=(const T& a, const T& b) { return SymBool(a.expr() != b.expr()); }
  friend SymBool operator<(const T& a, const T& b) { return SymBool(a.expr() < b.expr()); }
  friend SymBool operator<=(const T& a, const T& b) { return SymBool(a.expr() <= b.expr()); }
  friend SymBool operator>(const T& a, const T& b) { return SymBool(a.expr() > b.expr()); }
  friend SymBool operator>=(const T& a, const T& b) { return SymBool(a.expr() >= b.expr()); }
};

// A symbolic value of C++ type Rep (see the file comment).
template <SymRep Rep> class Sym : public TermComparisons<Sym<Rep>> {
public:
  using rep = Rep;

  // A literal (for example the `Num(0)` and `Num(-1)` of formula::edge_bias).
  explicit Sym(std::int64_t literal)
      : dom_(&Domain::active()), e_(dom_->ctx().int_val(literal)), text_(std::to_string(literal)) {
    // A literal that does not fit Rep would not compile in the modelled C++; record it anyway.
    dom_->require_fits<Rep>(e_, text_);
  }
  Sym(Domain& dom, z3::expr e, std::string text)
      : dom_(&dom), e_(std::move(e)), text_(std::move(text)) {}
  // A conversion from another modelled type (static_cast<Rep>(v) in the kernel): widening is
  // exact; narrowing records the obligation "v fits Rep" (else C++ would change the value).
  template <SymRep From>
  requires(!std::same_as<From, Rep>) explicit Sym(const Sym<From>& v)
      : dom_(&v.domain()), e_(v.expr()),
        text_(std::string("(") + type_name<Rep>() + ")" + v.text()) {
    if constexpr (sizeof(From) > sizeof(Rep))
      dom_->require_fits<Rep>(e_, text_);
  }

  [[nodiscard]] const z3::expr& expr() const { return e_; }
  [[nodiscard]] const std::string& text() const { return text_; }
  [[nodiscard]] Domain& domain() const { return *dom_; }

  friend Sym operator+(const Sym& a, const Sym& b) {
    return a.arith(a.e_ + b.e_, "(" + a.text_ + " + " + b.text_ + ")");
  }
  friend Sym operator-(const Sym& a, const Sym& b) {
    return a.arith(a.e_ - b.e_, "(" + a.text_ + " - " + b.text_ + ")");
  }
  friend Sym operator*(const Sym& a, const Sym& b) {
    return a.arith(a.e_ * b.e_, "(" + a.text_ + " * " + b.text_ + ")");
  }
  friend Sym operator-(const Sym& a) { return a.arith(-a.e_, "(-" + a.text_ + ")"); }

private:
  Sym arith(z3::expr r, std::string text) const {
    dom_->require_fits<Rep>(r, text);
    return Sym(*dom_, std::move(r), std::move(text));
  }

  Domain* dom_;
  z3::expr e_;
  std::string text_;
};

template <SymRep Rep> Sym<Rep> Domain::var(const std::string& name, Unit unit) {
  z3::expr v = ctx_.int_const(name.c_str());
  dom_register(name, v, unit);
  return Sym<Rep>(*this, v, name);
}

// Returns c ? t : f (a proof-side mirror of a C++ conditional on symbolic data). Performs no
// arithmetic, so records no obligation.
template <SymRep Rep> Sym<Rep> select(const SymBool& c, const Sym<Rep>& t, const Sym<Rep>& f) {
  return Sym<Rep>(t.domain(), z3::ite(c.expr(), t.expr(), f.expr()),
                  "select(" + t.text() + ", " + f.text() + ")");
}

// Returns c ? t : f for Booleans.
inline SymBool select(const SymBool& c, const SymBool& t, const SymBool& f) {
  return SymBool(z3::ite(c.expr(), t.expr(), f.expr()));
}

} // namespace rastrules::proofs
