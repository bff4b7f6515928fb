// SPDX-License-Identifier: MIT
// The proof runner and report (see prover.hpp).

#include "support/prover.hpp"

#include <z3++.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "rastrules/fixed.hpp"

namespace rastrules::proofs {
namespace {

// Interrupts the context's running check after `seconds` unless disarmed first (Z3's own
// timeout parameter is not honoured by every tactic, see proofs-notes pitfall 3).
class Watchdog {
public:
  Watchdog(z3::context& ctx, double seconds)
      : thread_([this, &ctx, seconds] {
          std::unique_lock<std::mutex> lock(mutex_);
          const auto limit = std::chrono::duration<double>(seconds);
          if (!cv_.wait_for(lock, limit, [this] { return done_; })) {
            ctx.interrupt();
          }
        }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

// The solver used for every query: normalise to a sum of monomials first (`som`), which keeps
// Z3 4.8.12's integer arithmetic from hanging on the products of the edge function (pitfall 3),
// then the default SMT core.
// Floating-point queries (Solver::kFloatingPoint) go to the QF_FP tactic instead, which
// bit-blasts them: seconds where the SMT core's floating-point theory takes minutes.
z3::solver make_solver(z3::context& ctx, Solver kind) {
  z3::params simp(ctx);
  simp.set("som", true);
  z3::tactic t = kind == Solver::kFloatingPoint
                     ? z3::tactic(ctx, "simplify") & z3::tactic(ctx, "qffp")
                     : z3::with(z3::tactic(ctx, "simplify"), simp) & z3::tactic(ctx, "smt");
  z3::solver s = t.mk_solver();
  z3::params p(ctx);
  p.set("timeout", static_cast<unsigned>(query_timeout_seconds() * 1000.0));
  s.set(p);
  return s;
}

struct CheckOutcome {
  z3::check_result result = z3::unknown;
  std::string reason;
};

CheckOutcome check(z3::solver& s, z3::context& ctx) {
  CheckOutcome out;
  try {
    Watchdog dog(ctx, query_timeout_seconds());
    out.result = s.check();
  } catch (const z3::exception& e) {
    out.result = z3::unknown;
    out.reason = e.msg();
    return out;
  }
  if (out.result == z3::unknown)
    out.reason = s.reason_unknown();
  return out;
}

std::string fixed_decimal(z3::context& ctx, const z3::expr& raw_value, int frac_bits,
                          const char* unit) {
  const z3::expr scale = ctx.real_val(static_cast<std::int64_t>(std::int64_t{1} << frac_bits));
  const z3::expr real = (z3::to_real(raw_value) / scale).simplify();
  if (!real.is_numeral())
    return "?";
  // frac_bits decimal digits represent raw / 2^frac_bits exactly.
  std::string s = real.get_decimal_string(frac_bits);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0')
      s.pop_back();
    if (!s.empty() && s.back() == '.')
      s.pop_back();
  }
  return s + " " + unit;
}

// Returns an IEEE-754 value of model m as "<decimal> (<hexadecimal>)", for the float and double
// formats (other formats as their IEEE bits).
std::string float_value(const z3::model& m, const z3::expr& e) {
  z3::context& ctx = e.ctx();
  if (m.eval(z3::expr(ctx, Z3_mk_fpa_is_nan(ctx, e)), true).is_true())
    return "NaN";
  const z3::expr bits = m.eval(z3::expr(ctx, Z3_mk_fpa_to_ieee_bv(ctx, e)), true);
  std::uint64_t u = 0;
  if (!bits.is_numeral_u64(u))
    return bits.to_string();
  const unsigned ebits = e.get_sort().fpa_ebits();
  const unsigned sbits = e.get_sort().fpa_sbits();
  char buf[96];
  if (ebits == 11 && sbits == 53) {
    double d = 0.0;
    static_assert(sizeof d == sizeof u);
    std::memcpy(&d, &u, sizeof d);
    std::snprintf(buf, sizeof buf, "%.17g (%a)", d, d);
  } else if (ebits == 8 && sbits == 24) {
    const auto u32 = static_cast<std::uint32_t>(u);
    float f = 0.0f;
    static_assert(sizeof f == sizeof u32);
    std::memcpy(&f, &u32, sizeof f);
    std::snprintf(buf, sizeof buf, "%.9g (%a)", static_cast<double>(f), static_cast<double>(f));
  } else {
    std::snprintf(buf, sizeof buf, "IEEE bits 0x%llx", static_cast<unsigned long long>(u));
  }
  return buf;
}

} // namespace

const char* to_string(Status s) {
  switch (s) {
  case Status::kProved:
    return "PROVED";
  case Status::kRefuted:
    return "REFUTED";
  case Status::kUnknown:
    return "UNKNOWN";
  }
  return "UNKNOWN";
}

double query_timeout_seconds() {
  if (const char* env = std::getenv("RASTRULES_PROOF_TIMEOUT")) {
    char* end = nullptr;
    const double v = std::strtod(env, &end);
    if (end != env && v > 0.0)
      return v;
  }
  return 30.0;
}

std::vector<Constant> kernel_constants() {
  return {
      {"kSubpixelBits", kSubpixelBits, Unit::kInteger},
      {"kSubpixelOne", kSubpixelOne, Unit::kCoordRaw},
      {"kSubpixelHalf", kSubpixelHalf, Unit::kCoordRaw},
      {"kMinVertexRaw", kMinVertexRaw, Unit::kCoordRaw},
      {"kMaxVertexRaw", kMaxVertexRaw, Unit::kCoordRaw},
      {"kMaxTargetSide", kMaxTargetSide, Unit::kInteger},
  };
}

std::vector<Constant> kernel_constants_and(const std::vector<Constant>& more) {
  std::vector<Constant> k = kernel_constants();
  k.insert(k.end(), more.begin(), more.end());
  return k;
}

std::string solver_version() {
  return std::string("Z3 ") + Z3_get_full_version();
}

std::string show_value(const z3::model& m, const z3::expr& e, Unit unit) {
  if (unit == Unit::kFloat)
    return float_value(m, e);
  const z3::expr v = m.eval(e, true);
  z3::context& ctx = e.ctx();
  if (unit == Unit::kBool) {
    if (v.is_true())
      return "true";
    if (v.is_false())
      return "false";
    return v.to_string();
  }
  std::string raw;
  if (!v.is_numeral(raw))
    return v.to_string();
  switch (unit) {
  case Unit::kCoordRaw:
    return raw + " raw [" + fixed_decimal(ctx, v, kSubpixelBits, "px") + "]";
  case Unit::kEdgeRaw:
    return raw + " raw [" + fixed_decimal(ctx, v, 2 * kSubpixelBits, "px^2") + "]";
  case Unit::kInteger:
  case Unit::kBool:
  case Unit::kFloat:
    break;
  }
  return raw;
}

Prover::Prover(Domain& dom, std::string obligation, std::string rules,
               std::vector<std::string> assumes, std::vector<Constant> constants)
    : dom_(dom), obligation_(std::move(obligation)) {
  std::cout << "proof " << obligation_ << "\n";
  std::cout << "  rule: " << rules << "\n";
  std::cout << "  solver: " << solver_version() << " (integer arithmetic, simplify:som then smt; "
            << query_timeout_seconds() << " s per query)\n";
  std::cout << "  constants (rastrules/fixed.hpp):\n";
  for (const Constant& c : constants) {
    z3::context& ctx = dom_.ctx();
    std::cout << "    " << c.name << " = ";
    const z3::expr v = ctx.int_val(c.value);
    switch (c.unit) {
    case Unit::kCoordRaw:
      std::cout << c.value << " raw [" << fixed_decimal(ctx, v, kSubpixelBits, "px") << "]";
      break;
    case Unit::kEdgeRaw:
      std::cout << c.value << " raw [" << fixed_decimal(ctx, v, 2 * kSubpixelBits, "px^2") << "]";
      break;
    case Unit::kInteger:
    case Unit::kBool:
    case Unit::kFloat:
      std::cout << c.value;
      break;
    }
    std::cout << "\n";
  }
  std::cout << "  assumes:";
  for (const std::string& a : assumes)
    std::cout << " " << a;
  std::cout << "\n";
  std::cout.flush();
}

void Prover::use_solver(Solver s) {
  solver_ = s;
  std::cout << "  solver for the following theorems: "
            << (s == Solver::kFloatingPoint
                    ? "IEEE-754 floating point (simplify then qffp, bit-blasting)"
                    : "integer arithmetic (simplify:som then smt)")
            << "\n";
  std::cout.flush();
}

void Prover::watch(const std::string& name, const z3::expr& value, Unit unit) {
  watches_.push_back(Watch{name, value, unit});
}

Status Prover::prove(const std::string& name, const std::vector<z3::expr>& hypotheses,
                     const z3::expr& goal, const std::vector<Obligation>& obligations) {
  z3::context& ctx = dom_.ctx();
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::vector<Watch> watches;
  watches.swap(watches_);

  Status status = Status::kUnknown;
  std::string note;
  std::vector<std::string> cex;

  // 1. The hypotheses must be satisfiable, or the theorem would hold vacuously.
  z3::solver pre = make_solver(ctx, solver_);
  for (const z3::expr& h : hypotheses)
    pre.add(h);
  const CheckOutcome sat_pre = check(pre, ctx);
  if (sat_pre.result == z3::unsat) {
    note = "hypotheses are unsatisfiable: the theorem would be vacuous";
  } else if (sat_pre.result == z3::unknown) {
    note = "could not show the hypotheses satisfiable: " + sat_pre.reason;
  } else {
    // 2. hypotheses AND NOT(goal AND obligations) must be unsatisfiable.
    z3::expr all = goal;
    for (const Obligation& o : obligations)
      all = all && o.holds;
    z3::solver s = make_solver(ctx, solver_);
    for (const z3::expr& h : hypotheses)
      s.add(h); // separately (proofs-notes pitfall 4)
    s.add(!all);
    const CheckOutcome r = check(s, ctx);
    if (r.result == z3::unsat) {
      status = Status::kProved;
    } else if (r.result == z3::unknown) {
      note = "solver gave up: " + r.reason;
    } else {
      status = Status::kRefuted;
      const z3::model m = s.get_model();
      cex.push_back("counterexample (raw fixed-point units, pixels in brackets):");
      for (const Watch& v : dom_.variables()) {
        if (!m.has_interp(v.value.decl()))
          continue;
        cex.push_back("  " + v.name + " = " + show_value(m, v.value, v.unit));
      }
      for (const Watch& w : watches) {
        cex.push_back("  " + w.name + " = " + show_value(m, w.value, w.unit));
      }
      if (m.eval(goal, true).is_false())
        cex.push_back("violated: the goal");
      for (const Obligation& o : obligations) {
        if (m.eval(o.holds, true).is_false()) {
          cex.push_back("violated: " + o.what + " (value " +
                        show_value(m, o.value, Unit::kInteger) + ")");
        }
      }
    }
  }

  char time_buf[32];
  std::snprintf(time_buf, sizeof time_buf, "%.2f", seconds());
  std::cout << to_string(status) << " " << name << " (" << time_buf << " s)";
  if (!note.empty())
    std::cout << " -- " << note;
  std::cout << "\n";
  for (const std::string& line : cex)
    std::cout << "    " << line << "\n";
  std::cout.flush();
  results_.emplace_back(name, status);
  return status;
}

Status Prover::skip(const std::string& name, const std::string& reason) {
  watches_.clear();
  std::cout << to_string(Status::kUnknown) << " " << name << " (0.00 s) -- " << reason << "\n";
  std::cout.flush();
  results_.emplace_back(name, Status::kUnknown);
  return Status::kUnknown;
}

int Prover::finish() {
  int passed = 0;
  int failed = 0;
  for (const auto& r : results_)
    (r.second == Status::kProved ? passed : failed) += 1;
  std::cout << obligation_ << ": " << passed << " passed, " << failed << " failed\n";
  std::cout.flush();
  return (failed == 0 && passed > 0) ? 0 : 1;
}

} // namespace rastrules::proofs
