// SPDX-License-Identifier: MIT
// Pictures of a rendered scene: the target magnified, its pixel grid and pixel centres, the
// primitives' snapped edges, covered pixels coloured by primitive and overlaps marked; for
// multisampled scenes every sample point (hollow), covered samples filled in the picture colour
// of the primitive that covered them last, pixels shared by primitives on different samples in
// grey (only samples covered twice count as overlap), helper lanes outlined dashed and
// centroids marked.
// Pictures only show results computed by the kernel; they decide nothing.

#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rastrules/io/image.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::io {

// Largest picture side in image pixels, and the magnification used when it fits.
inline constexpr int kMaxPictureSide = 4096;
inline constexpr int kDefaultPixelScale = 32;

// Returns the magnification (image pixels per target pixel) used by default: 32, or less so
// that the picture stays within kMaxPictureSide; 0 when even 1 does not fit.
[[nodiscard]] int default_picture_scale(std::int32_t width, std::int32_t height);

// Returns whether a picture of the target at `scale` fits within kMaxPictureSide.
[[nodiscard]] bool picture_fits(std::int32_t width, std::int32_t height, int scale);

// How many primitives cover each pixel of the target, and the first of them.
class CoverageMap {
public:
  CoverageMap(std::int32_t width, std::int32_t height);
  // coverage_q16: an antialiased line fragment's coverage: such fragments are blended by
  // coverage into the pixel's colour instead of being counted (so they never show as overlap).
  void add(std::uint32_t prim, std::int32_t x, std::int32_t y,
           std::optional<std::uint32_t> coverage_q16 = std::nullopt);
  [[nodiscard]] std::uint32_t count(std::int32_t x, std::int32_t y) const;
  [[nodiscard]] std::uint32_t first(std::int32_t x, std::int32_t y) const; // valid if count > 0
  // The blended colour of the antialiased fragments added at the pixel; nullopt when none.
  [[nodiscard]] std::optional<Rgb> aa_colour(std::int32_t x, std::int32_t y) const;
  [[nodiscard]] std::int32_t width() const { return width_; }
  [[nodiscard]] std::int32_t height() const { return height_; }

  // Multisampled scenes (SCENE.OUTPUT.MSAA). record_samples(n) makes add_fragment() also keep,
  // per sample, the last primitive that covered it, per pixel whether a helper lane ran there
  // and the last centroid. Costs 4n + 4 bytes a pixel; call it only when the picture shows
  // samples (samples_visible()).
  void record_samples(std::uint32_t sample_count);
  // Adds one kernel fragment: helper lanes are recorded but never counted as coverage, and
  // the per-sample fragments of one pixel of one primitive (sample shading) count once.
  void add_fragment(const Fragment& f);
  [[nodiscard]] bool has_samples() const { return sample_count_ != 0; }
  [[nodiscard]] std::uint32_t sample_count() const { return sample_count_; }
  // 1 + the primitive that last covered sample k of the pixel; 0 when none did.
  [[nodiscard]] std::uint32_t sample_owner(std::int32_t x, std::int32_t y, std::uint32_t k) const;
  [[nodiscard]] bool helper(std::int32_t x, std::int32_t y) const;
  // Whether some sample of the pixel was covered more than once.
  [[nodiscard]] bool sample_overlap(std::int32_t x, std::int32_t y) const;
  [[nodiscard]] std::optional<SampleOffset> centroid(std::int32_t x, std::int32_t y) const;

private:
  std::size_t index(std::int32_t x, std::int32_t y) const;
  std::int32_t width_;
  std::int32_t height_;
  std::vector<std::uint32_t> first_;
  std::vector<std::uint8_t> count_; // saturates at 255
  std::vector<Rgb> aa_;             // allocated on the first antialiased fragment
  std::vector<std::uint8_t> aa_seen_;
  std::uint32_t sample_count_ = 0;
  std::vector<std::uint32_t> owner_;         // width * height * sample_count_
  std::vector<std::uint8_t> helper_;         // width * height
  std::vector<std::uint8_t> sample_overlap_; // width * height
  std::vector<std::uint8_t> has_centroid_;   // width * height
  std::vector<SampleOffset> centroid_;       // width * height
  std::optional<Fragment> last_counted_;     // for sample shading: count a pixel once
};

// The smallest magnification at which pictures of multisampled scenes show sample points.
inline constexpr int kMinSampleScale = 8;

// Returns whether a picture at `scale` shows the sample points of the scene: a multisampled
// scene (more than one sample, or helper lanes, centroids or derivatives asked for) at a
// magnification of at least kMinSampleScale.
[[nodiscard]] bool samples_visible(const PreparedScene& scene, int scale);

// Colours: the fill of pixels covered by primitive `prim` alone, the colour of its edges, and
// the fill of pixels covered by more than one primitive.
[[nodiscard]] Rgb cover_colour(std::uint32_t prim);
[[nodiscard]] Rgb edge_colour(std::uint32_t prim);
inline constexpr Rgb kOverlapColour{255, 190, 190};
inline constexpr Rgb kOverlapMark{210, 20, 20};
inline constexpr Rgb kBackground{255, 255, 255};

// One line of a picture's legend: a swatch (a filled square, or a dot on white) and its meaning.
struct LegendEntry {
  Rgb colour;
  bool dot = false;
  std::string text;
};

// The legend of draw_picture's colours and marks; `samples`: the picture shows sample points
// (samples_visible), `aa`: it has antialiased or area-blended pixels.
[[nodiscard]] std::vector<LegendEntry> picture_legend(bool samples, bool aa);

// Returns the picture of a prepared scene and its coverage. The image is
// (width * scale + 1) x (height * scale + 1) pixels; target pixel (i, j) occupies image pixels
// [i * scale + 1, (i + 1) * scale) in x (and likewise in y), between grid lines.
// Preconditions: scale >= 1 and picture_fits(scene.width, scene.height, scale).
[[nodiscard]] Image draw_picture(const PreparedScene& scene, const CoverageMap& coverage,
                                 int scale);

// Returns a picture of a depth buffer (`render --png-depth`, SCENE.OUTPUT.PIPELINE): each target
// pixel grey, black at depth 0 (near) to white at 1 (far), from the mean of its samples' depths
// (depth01: width * height * samples values in [0, 1], index (y * width + x) * samples + k,
// clamped), with the pixel grid from scale 3 on. Image size as draw_picture().
// Preconditions: scale >= 1, picture_fits(width, height, scale), samples >= 1.
[[nodiscard]] Image draw_depth_picture(std::int32_t width, std::int32_t height,
                                       std::uint32_t samples, const std::vector<double>& depth01,
                                       int scale);

} // namespace rastrules::io
