// SPDX-License-Identifier: MIT
// Kernel/oracle comparison helpers.

#include "rastrules/gen/compare.hpp"

#include "rastrules/check/check.hpp"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <tuple>

namespace rastrules::gen {

oracle::State to_oracle_state(const RasterState& s) {
  return check::oracle_state(s); // the one kernel->oracle adapter (check/)
}

oracle::Scene to_oracle_scene(const TriScene& s) {
  oracle::Scene o;
  o.width = s.width;
  o.height = s.height;
  o.state = to_oracle_state(s.state);
  for (const GenTriangle& t : s.triangles)
    o.triangles.push_back(t.v);
  return o;
}

std::array<std::array<std::int64_t, 2>, 3> to_oracle_raw(const RawTriangle& t) {
  std::array<std::array<std::int64_t, 2>, 3> r{};
  for (std::size_t i = 0; i < 3; ++i)
    r[i] = {t[i][0], t[i][1]};
  return r;
}

std::string describe_difference(const std::vector<Fragment>& kernel,
                                const std::vector<oracle::Fragment>& oracle) {
  using Key = std::tuple<std::uint32_t, std::int32_t, std::int32_t>; // (prim, y, x)
  std::vector<Key> k, o;
  bool bad_mask = false;
  for (const Fragment& f : kernel) {
    k.emplace_back(f.prim, f.y, f.x);
    bad_mask = bad_mask || f.mask != 1u;
  }
  for (const oracle::Fragment& f : oracle)
    o.emplace_back(f.prim, f.y, f.x);
  if (k == o && !bad_mask)
    return "";
  std::ostringstream os;
  os << "kernel: " << k.size() << " fragments, oracle: " << o.size() << " fragments";
  if (bad_mask)
    os << "; a kernel fragment has mask != 1";
  if (!std::is_sorted(k.begin(), k.end()))
    os << "; kernel output is not sorted by (prim, y, x)";
  std::vector<Key> ks = k, os_ = o;
  std::sort(ks.begin(), ks.end());
  std::sort(os_.begin(), os_.end());
  std::vector<Key> only_k, only_o;
  std::set_difference(ks.begin(), ks.end(), os_.begin(), os_.end(), std::back_inserter(only_k));
  std::set_difference(os_.begin(), os_.end(), ks.begin(), ks.end(), std::back_inserter(only_o));
  const auto dump = [&os](const char* what, const std::vector<Key>& v) {
    os << "\n  " << what << " (" << v.size() << "):";
    for (std::size_t i = 0; i < v.size() && i < 40; ++i) {
      os << " {prim " << std::get<0>(v[i]) << ", x " << std::get<2>(v[i]) << ", y "
         << std::get<1>(v[i]) << "}";
    }
  };
  dump("only the kernel", only_k);
  dump("only the oracle", only_o);
  if (only_k.empty() && only_o.empty())
    os << "\n  (same sets; order or duplicates differ)";
  return os.str();
}

} // namespace rastrules::gen
