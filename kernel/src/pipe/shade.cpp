// SPDX-License-Identifier: MIT
// Stage 6 of run_pipeline: each fragment's depth (interpolated, converted, tested and written
// per sample) and attributes (barycentrics at the attribute's location, then perspective,
// linear or flat), on a depth target of tiles with fast clear and Hi-Z; tile by tile on
// several threads when binning, in fragment order within each tile.
// Implements: PIPE.BARY.EXACT, PIPE.BARY.LINE, PIPE.INTERP.LOCATION, PIPE.DEPTH.INTERP,
//   PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE, PIPE.DEPTH.KILL, PIPE.OPT.TILES, PIPE.OPT.HIZ,
//   PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR, PIPE.OPT.THREADS
#include <algorithm>
#include <atomic>

#include "rastrules/msaa.hpp"
#include "rastrules/parallel.hpp"
#include "stages.hpp"

namespace rastrules::pipe::detail {

namespace {

// rule: PIPE.BARY.LINE
// Returns the barycentrics of evaluation point s for a drawn primitive with snapped vertices v:
// the triangle's (PIPE.BARY.EXACT); for a line the exact projection parameter t = num / den
// as (den - num, num, 0) / den; for a point (1, 0, 0) / 1.
Barycentrics eval_bary(PrimitiveType type, const std::vector<Vec2>& v, Vec2 s) {
  if (type == PrimitiveType::kTriangle)
    return barycentrics({v[0], v[1], v[2]}, s);
  Barycentrics b;
  if (type == PrimitiveType::kPoint || v.size() < 2) {
    b.e = {1, 0, 0};
    b.area = 1;
    return b;
  }
  const std::int64_t dx = v[1].x.raw() - v[0].x.raw(), dy = v[1].y.raw() - v[0].y.raw();
  const std::int64_t px = s.x.raw() - v[0].x.raw(), py = s.y.raw() - v[0].y.raw();
  const std::int64_t den = dx * dx + dy * dy; // < 2^49
  const std::int64_t num = px * dx + py * dy; // |.| < 2^49
  b.e = {den - num, num, 0};
  b.area = den;
  return b;
}

// The depth buffer in tiles of T x T pixels, with fast clear and Hi-Z (PIPE.OPT.*). A tile's
// state is touched only by fragments in that tile, so tiles may be shaded on several threads.
class DepthTarget {
public:
  DepthTarget(const Scene& s, const PipeOptions& o, const std::vector<Drawn>& drawn,
              std::vector<DepthValue>& buffer)
      : s_(s), drawn_(drawn), buffer_(buffer), T_(o.tile_size), n_(s.msaa.count()),
        fmt_(s.depth ? s.conventions.depth : DepthFormat::kD24), tiles_x_((s.width + T_ - 1) / T_),
        tiles_y_((s.height + T_ - 1) / T_),
        clear_(s.depth ? to_depth_format(s.depth->clear, 0.0f, 1.0f, fmt_) : DepthValue{}) {
    const bool less_like = s.depth && (s.depth->func == CompareFunc::kLess ||
                                       s.depth->func == CompareFunc::kLessEqual);
    const bool greater_like = s.depth && (s.depth->func == CompareFunc::kGreater ||
                                          s.depth->func == CompareFunc::kGreaterEqual);
    less_like_ = less_like;
    use_hiz_ = o.hiz && (less_like || greater_like);
    if (!s.depth)
      return;
    const std::size_t samples =
        static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height) * n_;
    if (o.fast_clear) {
      buffer_.resize(samples);
      cleared_.assign(ntiles(), 1);
    } else {
      buffer_.assign(samples, clear_);
    }
    if (use_hiz_) {
      dirty_.assign(ntiles(), 0);
      bound_.assign(ntiles(), clear_);
      checked_.assign(ntiles(), 0);
      rejected_.assign(ntiles(), 0);
    }
  }

  [[nodiscard]] std::size_t ntiles() const { return static_cast<std::size_t>(tiles_x_ * tiles_y_); }
  [[nodiscard]] std::size_t tile_of(std::int64_t x, std::int64_t y) const {
    return static_cast<std::size_t>((y / T_) * tiles_x_ + x / T_);
  }
  [[nodiscard]] std::size_t sample_index(std::int64_t x, std::int64_t y, std::uint32_t k) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(s_.width) +
            static_cast<std::size_t>(x)) *
               n_ +
           k;
  }
  [[nodiscard]] bool use_hiz() const { return use_hiz_; }

  // The stored value of sample si in tile t (the clear value while the tile is fast-cleared).
  [[nodiscard]] DepthValue old(std::size_t t, std::size_t si) const {
    return (!cleared_.empty() && cleared_[t]) ? clear_ : buffer_[si];
  }

  // rule: PIPE.DEPTH.WRITE
  void write(std::size_t t, std::size_t si, const DepthValue& v) {
    materialize(t);
    buffer_[si] = v;
    if (use_hiz_)
      dirty_[t] = 1;
  }

  // rule: PIPE.OPT.HIZ
  // Whether every covered sample of drawn primitive p in tile t fails the test.
  bool hiz_rejects(std::size_t p, std::size_t t) {
    if (checked_[t] == p + 1)
      return rejected_[t] != 0;
    if (dirty_[t]) {
      bool first = true;
      DepthValue b = clear_;
      if (cleared_.empty() || !cleared_[t]) {
        for_tile(t, [&](std::size_t i) {
          const DepthValue& v = buffer_[i];
          if (first || (less_like_ ? stored_less(b, v) : stored_less(v, b)))
            b = v;
          first = false;
        });
      }
      bound_[t] = b;
      dirty_[t] = 0;
    }
    const Drawn& d = drawn_[p];
    bool reject = false;
    if (d.bounded) {
      const CompareFunc f = s_.depth->func;
      // less: new < old fails for all when lo >= max; less_equal: when lo > max.
      if (f == CompareFunc::kLess)
        reject = !stored_less(d.lo, bound_[t]);
      if (f == CompareFunc::kLessEqual)
        reject = stored_less(bound_[t], d.lo);
      if (f == CompareFunc::kGreater)
        reject = !stored_less(bound_[t], d.hi);
      if (f == CompareFunc::kGreaterEqual)
        reject = stored_less(d.hi, bound_[t]);
    }
    checked_[t] = p + 1;
    rejected_[t] = reject ? 1 : 0;
    if (reject)
      hiz_rejected.fetch_add(1, std::memory_order_relaxed);
    return reject;
  }

  // Fills every tile still fast-cleared; returns how many there were.
  std::uint64_t finish() {
    std::uint64_t never = 0;
    for (std::size_t t = 0; t < cleared_.size(); ++t) {
      never += cleared_[t];
      materialize(t);
    }
    return never;
  }

  std::atomic<std::uint64_t> hiz_rejected{0};

private:
  // Calls fn(index) for each sample of tile t.
  template <class Fn> void for_tile(std::size_t t, Fn&& fn) const {
    const std::int64_t tx = static_cast<std::int64_t>(t) % tiles_x_,
                       ty = static_cast<std::int64_t>(t) / tiles_x_;
    for (std::int64_t y = ty * T_; y < std::min<std::int64_t>((ty + 1) * T_, s_.height); ++y)
      for (std::int64_t x = tx * T_; x < std::min<std::int64_t>((tx + 1) * T_, s_.width); ++x)
        for (std::uint32_t k = 0; k < n_; ++k)
          fn(sample_index(x, y, k));
  }
  // rule: PIPE.OPT.FAST_CLEAR
  void materialize(std::size_t t) {
    if (!cleared_.empty() && cleared_[t]) {
      for_tile(t, [&](std::size_t i) { buffer_[i] = clear_; });
      cleared_[t] = 0;
    }
  }
  [[nodiscard]] bool stored_less(const DepthValue& a, const DepthValue& b) const {
    return fmt_ == DepthFormat::kD32F ? a.f < b.f : a.unorm < b.unorm;
  }

  const Scene& s_;
  const std::vector<Drawn>& drawn_;
  std::vector<DepthValue>& buffer_;
  const std::int64_t T_;
  const std::uint32_t n_;
  const DepthFormat fmt_;
  const std::int64_t tiles_x_, tiles_y_;
  const DepthValue clear_;
  bool less_like_ = false, use_hiz_ = false;
  std::vector<std::uint8_t> cleared_;  // fast clear: the tile still holds only the clear value
  std::vector<std::uint8_t> dirty_;    // Hi-Z: the tile's bound must be recomputed
  std::vector<DepthValue> bound_;      // Hi-Z: max (less-like) or min (greater-like) of the tile
  std::vector<std::size_t> checked_;   // Hi-Z: drawn primitive last checked in the tile, + 1
  std::vector<std::uint8_t> rejected_; // Hi-Z: whether that primitive was rejected there
};

} // namespace

void shade(const Scene& s, const PreparedScene& ps, const Viewport& vp, const PipeOptions& o,
           const std::vector<Drawn>& drawn, const Links& links, PipeResult& result) {
  const SamplePattern& pattern = ps.msaa.pattern;
  const DepthFormat fmt = s.depth ? s.conventions.depth : DepthFormat::kD24;
  const std::size_t nattr = s.attributes.size();
  const std::uint32_t nsamples = s.msaa.count();
  const std::vector<Fragment>& fragments = result.fragments;
  DepthTarget target(s, o, drawn, result.depth_buffer);
  std::atomic<std::uint64_t> n_depth{0}, n_attr{0}; // PipeStats

  // Depth and attributes of fragment i.
  const auto shade_one = [&](std::size_t i) {
    const Fragment& f = fragments[i];
    const std::size_t p = links.drawn_of[i];
    const Drawn& d = drawn[p];
    const std::vector<float>& flat = result.drawn[p].flat;
    FragmentData& out = result.data[i];
    const Vec2 centre = pixel_center(f.x, f.y);
    const auto point_of = [&](Location l) {
      if (l == Location::kCentroid && f.centroid)
        return sample_position(f.x, f.y, f.centroid->offset);
      if (l == Location::kSample && f.sample)
        return sample_position(f.x, f.y, pattern.positions[*f.sample]);
      return centre;
    };
    // rule: PIPE.INTERP.LOCATION
    const Location first = nattr > 0 ? s.attributes[0].location : Location::kCenter;
    const auto interpolate = [&]() {
      out.bary = eval_bary(d.type, d.v, point_of(first));
      n_attr.fetch_add(nattr, std::memory_order_relaxed);
      out.attr.reserve(nattr);
      for (std::size_t a = 0; a < nattr; ++a) {
        const AttributeDecl& decl = s.attributes[a];
        const Barycentrics b =
            decl.location == first ? *out.bary : eval_bary(d.type, d.v, point_of(decl.location));
        switch (decl.interpolation) {
        case Interpolation::kPerspective:
          out.attr.push_back(interpolate_perspective(b, d.a[a], d.w, flat[a]));
          break;
        case Interpolation::kLinear:
          out.attr.push_back(interpolate_linear(b, d.a[a]));
          break;
        case Interpolation::kFlat:
          out.attr.push_back(flat[a]);
          break;
        }
      }
    };
    // rule: PIPE.OPT.EARLY_Z
    if (!o.early_z)
      interpolate(); // late: attributes first, dropped below if the fragment is killed
    if (s.depth && !f.helper) {
      // rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE
      const std::size_t t = target.tile_of(f.x, f.y);
      out.passed = 0;
      if (!(target.use_hiz() && target.hiz_rejects(p, t))) {
        for (std::uint32_t k = 0; k < nsamples; ++k) {
          if ((f.mask & (1u << k)) == 0)
            continue;
          n_depth.fetch_add(1, std::memory_order_relaxed);
          const Barycentrics b =
              eval_bary(d.type, d.v, sample_position(f.x, f.y, pattern.positions[k]));
          const DepthValue dv =
              to_depth_format(interpolate_depth(b, d.z), vp.min_depth, vp.max_depth, fmt);
          out.depth.push_back(dv);
          const std::size_t si = target.sample_index(f.x, f.y, k);
          if (depth_test(s.depth->func, dv, target.old(t, si), fmt)) {
            out.passed |= 1u << k;
            if (s.depth->write)
              target.write(t, si, dv);
          }
        }
      }
      // rule: PIPE.DEPTH.KILL
      if (out.passed == 0) {
        out.depth.clear();
        out.attr.clear();
        out.bary.reset();
        return;
      }
    }
    if (o.early_z)
      interpolate();
  };

  // rule: PIPE.OPT.TILES, PIPE.OPT.THREADS
  if (o.binning && s.depth) {
    // Bin the fragments by tile (each bin in fragment order), then shade tile by tile; tiles
    // share no sample, so they may run on several threads.
    std::vector<std::vector<std::size_t>> bins(target.ntiles());
    for (std::size_t i = 0; i < fragments.size(); ++i)
      bins[target.tile_of(fragments[i].x, fragments[i].y)].push_back(i);
    run_units(target.ntiles(), std::max(1u, o.render.threads), [&](std::size_t t) {
      for (const std::size_t i : bins[t])
        shade_one(i);
    });
  } else {
    for (std::size_t i = 0; i < fragments.size(); ++i)
      shade_one(i);
  }
  result.stats.tiles_never_written += target.finish();
  result.stats.hiz_rejected = target.hiz_rejected.load();
  result.stats.depth_samples = n_depth.load();
  result.stats.attributes = n_attr.load();
}

} // namespace rastrules::pipe::detail
