// SPDX-License-Identifier: MIT
// The rule IDs the kernel's decision records name and the tools print, in one table.
// Every ID here is defined in spec/ (a level-3 heading of spec/**/*.md): tools/trace/trace.py
// reads this table and fails on an ID the registry does not define, so renaming a rule cannot
// leave a stale ID in what users see. Add an ID here before printing it; one entry per line,
// in the form `inline constexpr RuleId kName{"ID"};` (the form trace.py reads).

#pragma once

#include <string_view>

namespace rastrules {

// A rule ID of the registry, e.g. "TRI.FILL.TOP_LEFT".
struct RuleId {
  std::string_view id;
  friend constexpr bool operator==(RuleId, RuleId) = default;
};

namespace rules {

// Coordinates and snapping (spec/conventions.md, spec/rules/snap.md).
inline constexpr RuleId kCoordPixelCenter{"COORD.PIXEL.CENTER"};
inline constexpr RuleId kSnapVertexRound{"SNAP.VERTEX.ROUND"};
inline constexpr RuleId kSnapCullAfterSnap{"SNAP.CULL.AFTER_SNAP"};

// Triangles (spec/rules/tri.md).
inline constexpr RuleId kTriEdgeFunction{"TRI.EDGE.FUNCTION"};
inline constexpr RuleId kTriOrientArea{"TRI.ORIENT.AREA"};
inline constexpr RuleId kTriOrientNormalise{"TRI.ORIENT.NORMALISE"};
inline constexpr RuleId kTriDegenerateZeroArea{"TRI.DEGENERATE.ZERO_AREA"};
inline constexpr RuleId kTriCullMode{"TRI.CULL.MODE"};
inline constexpr RuleId kTriFillTopEdge{"TRI.FILL.TOP_EDGE"};
inline constexpr RuleId kTriFillLeftEdge{"TRI.FILL.LEFT_EDGE"};
inline constexpr RuleId kTriFillTopLeft{"TRI.FILL.TOP_LEFT"};
inline constexpr RuleId kTriFillConvention{"TRI.FILL.CONVENTION"};
inline constexpr RuleId kTriCoverSample{"TRI.COVER.SAMPLE"};

// Points and lines (spec/scene.md, spec/rules/point.md, line.md, line_aa.md, line_quad.md).
inline constexpr RuleId kScenePrimPoint{"SCENE.PRIM.POINT"};
inline constexpr RuleId kSceneLineMode{"SCENE.LINE_MODE"};
inline constexpr RuleId kSceneOutputCoverage{"SCENE.OUTPUT.COVERAGE"};
inline constexpr RuleId kSceneMsaa{"SCENE.MSAA"};
inline constexpr RuleId kLineD3DExit{"LINE.D3D.EXIT"};
inline constexpr RuleId kLineVkExit{"LINE.VK.EXIT"};
inline constexpr RuleId kLineD3DTestArea{"LINE.D3D.TEST_AREA"};
inline constexpr RuleId kLineVkTestArea{"LINE.VK.TEST_AREA"};
inline constexpr RuleId kLineZeroLength{"LINE.ZERO_LENGTH"};
inline constexpr RuleId kLineAAFragment{"LINE.AA.FRAGMENT"};

// Multisampling (spec/rules/msaa.md).
inline constexpr RuleId kMsaaPatternGrid{"MSAA.PATTERN.GRID"};
inline constexpr RuleId kMsaaPatternStandard{"MSAA.PATTERN.STANDARD"};
inline constexpr RuleId kMsaaPatternCenter{"MSAA.PATTERN.CENTER"};
inline constexpr RuleId kMsaaPatternCustom{"MSAA.PATTERN.CUSTOM"};
inline constexpr RuleId kMsaaSamplePosition{"MSAA.SAMPLE.POSITION"};
inline constexpr RuleId kMsaaCoverSample{"MSAA.COVER.SAMPLE"};
inline constexpr RuleId kMsaaLineMode{"MSAA.LINE.MODE"};
inline constexpr RuleId kMsaaMaskAnd{"MSAA.MASK.AND"};
inline constexpr RuleId kMsaaCentroidD3D11{"MSAA.CENTROID.D3D11"};
inline constexpr RuleId kMsaaCentroidD3D10{"MSAA.CENTROID.D3D10"};
inline constexpr RuleId kMsaaQuadHelper{"MSAA.QUAD.HELPER"};

// The pipeline (spec/scene.md, spec/rules/pipe.md).
inline constexpr RuleId kScenePipeline{"SCENE.PIPELINE"};
inline constexpr RuleId kPipeBaryExact{"PIPE.BARY.EXACT"};
inline constexpr RuleId kPipeBaryLine{"PIPE.BARY.LINE"};
inline constexpr RuleId kPipeDepthKill{"PIPE.DEPTH.KILL"};
inline constexpr RuleId kPipeDepthTest{"PIPE.DEPTH.TEST"};

// 2D paths (spec/scene.md, spec/rules/path.md).
inline constexpr RuleId kScenePrimPath{"SCENE.PRIM.PATH"};
inline constexpr RuleId kSceneOutputArea{"SCENE.OUTPUT.AREA"};
inline constexpr RuleId kPathWinding{"PATH.WINDING"};
inline constexpr RuleId kPathSampleTie{"PATH.SAMPLE.TIE"};
inline constexpr RuleId kPathFillRule{"PATH.FILL.RULE"};
inline constexpr RuleId kPathContourClose{"PATH.CONTOUR.CLOSE"};
inline constexpr RuleId kPathAreaExact{"PATH.AREA.EXACT"};
inline constexpr RuleId kPathAreaCurve{"PATH.AREA.CURVE"};

} // namespace rules
} // namespace rastrules
