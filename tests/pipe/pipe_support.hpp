// SPDX-License-Identifier: MIT
// Shared by tests/pipe: a pipeline scene's result, a failed test (naming the error) when the
// scene is refused.

#pragma once

#include <variant>

#include <gtest/gtest.h>

#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::pipe::test_support {

inline PipeResult run(const Scene& s, const PipeOptions& o = {}) {
  auto r = run_pipeline(s, o);
  if (auto* e = std::get_if<SceneError>(&r)) {
    ADD_FAILURE() << e->what();
    return {};
  }
  return std::get<PipeResult>(r);
}

} // namespace rastrules::pipe::test_support
