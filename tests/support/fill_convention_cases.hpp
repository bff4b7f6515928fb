// SPDX-License-Identifier: MIT
// The fill-convention examples shared by the triangle tests (TRI.FILL.CONVENTION) and the path
// tests (PATH.SAMPLE.TIE, which must give the same answers on one-triangle paths): samples on
// edges and vertices and whether each convention covers them.

#pragma once

#include <array>
#include <ostream>

#include "support.hpp"

namespace rastrules::test {

// One sample on a triangle's boundary and whether it is inside under each convention.
struct ConventionCase {
  const char* name;
  std::array<Px, 3> tri; // pixels, any winding
  Px sample;
  bool top_left, top_right, bottom_left, bottom_right;
};

// Triangles (pixels):
//   UL = (0,0) (4,0) (0,4): top edge y = 0, left edge x = 0, right edge x + y = 4.
//   LR = (0,4) (4,0) (4,4): bottom edge y = 4, right edge x = 4, left edge x + y = 4.
//   AL = (4,0) (4,4) (0,2): arrow pointing left, (0,2) joins two left edges.
//   AR = (0,0) (4,2) (0,4): arrow pointing right, (4,2) joins two right edges.
//   UP = (2,0) (4,4) (0,4): apex (2,0) joins a left and a right edge.
//   BL = (0,0) (4,4) (0,4): (0,4) joins a bottom and a left edge.
//   BR = (4,0) (4,4) (0,4): (4,4) joins a bottom and a right edge.
// clang-format off
inline const ConventionCase kConventionCases[] = {
  //  name                        triangle                           sample       TL     TR     BL     BR
  {"OnTopEdge",                  {{{0, 0}, {4, 0}, {0, 4}}},         {1.5, 0},    true,  true,  false, false},
  {"OnBottomEdge",               {{{0, 4}, {4, 0}, {4, 4}}},         {2.5, 4},    false, false, true,  true},
  {"OnVerticalLeftEdge",         {{{0, 0}, {4, 0}, {0, 4}}},         {0, 1.5},    true,  false, true,  false},
  {"OnDiagonalRightEdge",        {{{0, 0}, {4, 0}, {0, 4}}},         {2, 2},      false, true,  false, true},
  {"OnVerticalRightEdge",        {{{0, 4}, {4, 0}, {4, 4}}},         {4, 2.5},    false, true,  false, true},
  {"OnDiagonalLeftEdge",         {{{0, 4}, {4, 0}, {4, 4}}},         {2, 2},      true,  false, true,  false},
  {"VertexTopAndLeft",           {{{0, 0}, {4, 0}, {0, 4}}},         {0, 0},      true,  false, false, false},
  {"VertexTopAndRight",          {{{0, 0}, {4, 0}, {0, 4}}},         {4, 0},      false, true,  false, false},
  {"VertexBottomAndLeft",        {{{0, 0}, {4, 4}, {0, 4}}},         {0, 4},      false, false, true,  false},
  {"VertexBottomAndRight",       {{{4, 0}, {4, 4}, {0, 4}}},         {4, 4},      false, false, false, true},
  {"VertexTwoLeftEdges",         {{{4, 0}, {4, 4}, {0, 2}}},         {0, 2},      true,  false, true,  false},
  {"VertexTwoRightEdges",        {{{0, 0}, {4, 2}, {0, 4}}},         {4, 2},      false, true,  false, true},
  {"VertexLeftAndRightAtTop",    {{{2, 0}, {4, 4}, {0, 4}}},         {2, 0},      false, false, false, false},
  {"VertexLeftAndRightAtBottom", {{{0, 0}, {4, 0}, {2, 4}}},         {2, 4},      false, false, false, false},
  {"StrictlyInside",             {{{0, 0}, {4, 0}, {0, 4}}},         {1, 1},      true,  true,  true,  true},
  {"StrictlyOutside",            {{{0, 0}, {4, 0}, {0, 4}}},         {3, 3},      false, false, false, false},
  {"CounterClockwiseOnTopEdge",  {{{0, 0}, {0, 4}, {4, 0}}},         {1.5, 0},    true,  true,  false, false},
  {"CounterClockwiseOnLeftEdge", {{{0, 0}, {0, 4}, {4, 0}}},         {0, 1.5},    true,  false, true,  false},
};
// clang-format on

// Names the case in gtest output instead of dumping its bytes.
inline void PrintTo(const ConventionCase& c, std::ostream* os) {
  *os << c.name;
}

} // namespace rastrules::test
