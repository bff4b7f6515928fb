// SPDX-License-Identifier: MIT
// The legend of a finding's picture, shared by the picture (report.cpp draws it below the
// panels) and the campaign's page (html_report.cpp lists it beside the picture).

#pragma once

#include <string>
#include <vector>

#include "rastrules/io/picture.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::fuzzer {

// One line of the legend: a swatch (a filled square, or a dot on white) and its meaning.
using LegendLine = io::LegendEntry;

// The legend of the picture of a finding of `scene` (sample lines when it is multisampled).
// rule: FUZZ.REPORT
[[nodiscard]] std::vector<LegendLine> difference_legend(const Scene& scene);

} // namespace rastrules::fuzzer
