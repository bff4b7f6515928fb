// SPDX-License-Identifier: MIT
// Shared by the fuzz targets: a byte decoder (in the manner of libFuzzer's FuzzedDataProvider,
// written here so that gcc builds need nothing from clang), the decoder of small scenes, the
// oracles' reading of a scene's validity, and the failure report. The comparison of the
// kernel with the exact oracles is check::check_against_oracle (check/).

#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/scene.hpp"

namespace rastrules::fuzz {

// Reads integers from the front of a byte string; past its end every read gives zero bytes.
class ByteReader {
public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte();
  std::uint16_t u16(); // little-endian
  std::uint32_t u24(); // little-endian, in [0, 2^24)
  std::uint32_t u32(); // little-endian
  [[nodiscard]] std::size_t remaining() const { return size_ - pos_; }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// The limits of decoded scenes.
inline constexpr std::int32_t kMaxFuzzTarget = 64;   // width and height in [1, 64]
inline constexpr std::size_t kMaxFuzzPrimitives = 8; // [0, 8] primitives
inline constexpr std::size_t kMaxStripVertices = 5;  // line strips: [2, 5] vertices
// At most 2 antialiased segments per scene (further "aa" flags are dropped): the exact AA
// oracle takes milliseconds per pixel under the sanitizers, and one input must stay well
// within libFuzzer's -timeout.
inline constexpr std::size_t kMaxAaSegments = 2;

// Returns the scene the bytes describe (fuzz/README.md gives the layout): target 1..64 px,
// any cull / front_face / fill / line_mode, up to 8 primitives of every type (antialiased
// lines and strips included), each coordinate from one of: a raw 16.8 value near the target,
// any raw 16.8 value of SNAP.VERTEX.RANGE, a rounding tie between two raw values, a few ulps
// from a raw value, or arbitrary float32 bits (NaN, infinities, out of range).
[[nodiscard]] Scene decode_scene(ByteReader& in);

// The limits of decode_path_scene: small targets and paths, so that the exact oracle's
// arrangements stay quick.
inline constexpr std::int32_t kMaxFuzzPathTarget = 24; // width and height in [1, 24]
inline constexpr std::size_t kMaxFuzzPaths = 3;        // [1, 3] path primitives
inline constexpr std::size_t kMaxFuzzPathContours = 3; // [1, 3] contours each
inline constexpr std::size_t kMaxFuzzPathSegments = 8; // [1, 8] segments each

// Decodes bytes into a scene of path primitives (SCENE.PRIM.PATH): target, fill convention,
// 1, 4 or 16 samples and a sample mask, then per path its fill rule, coverage kind ("area"
// for paths of lines, and sometimes with curves, PATH.AREA.CURVE), contours of
// lines, quadratics and cubics whose points are mostly raw values near the target (often
// multiples of 8 raw: on pixel centres and sample rows), sometimes decode_scene's coordinates.
[[nodiscard]] Scene decode_path_scene(ByteReader& in);

// The scene an external driver's output is checked against, chosen by one byte (the
// protocol targets): width and height in {1, 3, 8, 16}, 1 or 4 samples, 1 to 4 primitives
// (points, whose content does not matter to the reader).
[[nodiscard]] Scene protocol_scene(std::uint8_t b);

// Returns why `scene` is invalid by the oracles' reading of spec/scene.md (a coordinate that
// does not snap, a point outside POINT.RANGE, aa outside line mode d3d, a wrong vertex count,
// a target size outside [1, 16384], a sample mask wider than the pattern, sample shading of
// Bresenham lines or quadrilateral lines on a centre pattern with several samples), or an
// empty string when they find it valid.
[[nodiscard]] std::string oracle_invalid_reason(const Scene& scene);

// Prints the failure, the scene file that reproduces it and the input bytes (hex) to stderr,
// then aborts (libFuzzer saves the input as crash-*).
[[noreturn]] void fail(const std::string& what, const std::vector<std::string>& details,
                       const Scene* scene, const std::uint8_t* data, std::size_t size);

// Fails when `e`, an error of `stage` (read_scene, prepare, run_pipeline), has no message or
// names neither a field nor the parser's position (SCENE.INPUT.ERRORS). scene: the reproducer,
// or null.
void check_scene_error(const SceneError& e, const char* stage, const Scene* scene,
                       const std::uint8_t* data, std::size_t size);

// Reads the input bytes as scene text: nullopt when they are longer than io::kMaxSceneBytes or
// when read_scene rejects them (after check_scene_error on its error).
[[nodiscard]] std::optional<Scene> read_input_scene(const std::uint8_t* data, std::size_t size);

// Fails when the text write_scene writes for `scene` does not read back to the same scene
// (SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32).
void check_round_trip(const Scene& scene, const std::uint8_t* data, std::size_t size);

// Fails when prepare()'s verdict on `scene` (`prepared`, its result) is not the oracles'
// (oracle_invalid_reason): prepare() must accept exactly the scenes they find valid.
void check_prepare_verdict(const Scene& scene,
                           const std::variant<PreparedScene, SceneError>& prepared,
                           const std::uint8_t* data, std::size_t size);

// A scene prepare() accepted and its fragments.
struct Drawn {
  PreparedScene prepared;
  std::vector<Fragment> fragments;
};

// Prepares `scene` (an error must name a field; the verdict must be the oracles',
// check_prepare_verdict) and, when it is accepted, rasterizes it twice and renders it: fails
// when the runs differ or render() differs from rasterize(prepare()). nullopt when rejected.
[[nodiscard]] std::optional<Drawn> prepare_and_draw(const Scene& scene, const std::uint8_t* data,
                                                    std::size_t size);

// Fails, naming `what` and the mismatches, when check::check_against_oracle finds the kernel's
// fragments of `drawn` different from the exact oracles' (or an oracle throws).
void check_against_oracles(const Scene& scene, const Drawn& drawn, const std::string& what,
                           const std::uint8_t* data, std::size_t size);

} // namespace rastrules::fuzz
