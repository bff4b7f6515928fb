// SPDX-License-Identifier: MIT
// Out of memory at every allocation of a C API call: the call returns RR_ERROR_OUT_OF_MEMORY
// (or succeeds), its outputs stay NULL, and no exception crosses the C interface (one would
// end the program: every entry point is noexcept). The allocations are made to fail by this
// executable's own operator new, armed for one call at a time; not under AddressSanitizer,
// whose allocator this would bypass (the sanitizer stage checks leaks instead).
// Not the JSON form of rr_explain: nlohmann::json's destructor allocates (json_value::destroy
// keeps a stack of children), so an allocation that fails while a JSON value is destroyed
// during unwinding ends the program in nlohmann's noexcept destructor.

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <new>
#include <string>

#include "rastrules/rastrules.h"

// Under AddressSanitizer (gcc says __SANITIZE_ADDRESS__, clang 14 only __has_feature) the
// replaced operator new would pair with the sanitizer's delete: the test is left out there.
#if defined(__SANITIZE_ADDRESS__)
#define RASTRULES_CAPI_OOM 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RASTRULES_CAPI_OOM 0
#else
#define RASTRULES_CAPI_OOM 1
#endif
#else
#define RASTRULES_CAPI_OOM 1
#endif

#if RASTRULES_CAPI_OOM
namespace {
// Allocations left before operator new fails on this thread; negative: never fails.
thread_local long t_allocations_left = -1;
} // namespace

void* operator new(std::size_t n) {
  if (t_allocations_left == 0)
    throw std::bad_alloc();
  if (t_allocations_left > 0)
    --t_allocations_left;
  if (void* p = std::malloc(n == 0 ? 1 : n))
    return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
#endif

namespace {

const std::string kScene = R"({"target": {"width": 16, "height": 8}, "samples": 4,
  "primitives": [{"type": "triangle", "v": [[1, 1], [9.5, 2], [2, 7.25]]},
                 {"type": "line_strip", "v": [[0.5, 0.5], [8, 7], [15, 1]]}]})";

#if RASTRULES_CAPI_OOM
// Runs call with 0, 1, 2, ... allocations allowed until it succeeds; every failure must be
// RR_ERROR_OUT_OF_MEMORY with a message. Returns the number of failed attempts.
template <class F> int until_it_succeeds(F call) {
  for (long budget = 0; budget < 100000; ++budget) {
    t_allocations_left = budget;
    const rr_status s = call();
    t_allocations_left = -1;
    if (s == RR_OK)
      return static_cast<int>(budget);
    EXPECT_EQ(s, RR_ERROR_OUT_OF_MEMORY)
        << "with " << budget << " allocations: " << rr_last_error();
    EXPECT_STRNE(rr_last_error(), "");
  }
  ADD_FAILURE() << "never succeeded";
  return -1;
}
#endif

TEST(CApiMemory, EveryAllocationFailureIsOutOfMemory) {
#if !RASTRULES_CAPI_OOM
  GTEST_SKIP() << "operator new is AddressSanitizer's here";
#else
  rr_scene* scene = nullptr;
  const int read = until_it_succeeds([&] {
    const rr_status s = rr_scene_from_json(kScene.data(), kScene.size(), &scene);
    if (s != RR_OK) {
      EXPECT_EQ(scene, nullptr);
    }
    return s;
  });
  EXPECT_GT(read, 0);
  ASSERT_NE(scene, nullptr);
  rr_render* render = nullptr;
  EXPECT_GT(until_it_succeeds([&] {
              const rr_status s = rr_render_scene(scene, nullptr, &render);
              if (s != RR_OK) {
                EXPECT_EQ(render, nullptr);
              }
              return s;
            }),
            0);
  char* text = nullptr;
  EXPECT_GT(until_it_succeeds([&] { return rr_explain(scene, 3, 3, 0, &text); }), 0);
  EXPECT_GT(until_it_succeeds([&] { return rr_scene_set_profile(scene, "vulkan"); }), 0);
  rr_string_free(text);
  rr_render_free(render);
  rr_scene_free(scene);
#endif
}

} // namespace
