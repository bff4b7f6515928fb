# Helpers shared by every folder: warnings, sanitizers, test registration.

add_library(rastrules_warnings INTERFACE)
target_compile_options(rastrules_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wshadow
  $<$<BOOL:${RASTRULES_WERROR}>:-Werror>)

add_library(rastrules_sanitize INTERFACE)
if(RASTRULES_SANITIZE)
  string(REPLACE ";" "," _rastrules_san "${RASTRULES_SANITIZE}")
  target_compile_options(rastrules_sanitize INTERFACE
    -fsanitize=${_rastrules_san} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  target_link_options(rastrules_sanitize INTERFACE -fsanitize=${_rastrules_san})
endif()

# Third-party headers are system headers: their warnings are not ours.
# rastrules_add_gtest(NAME <exe> AREA <area> KIND <unit|property> SOURCES ... LIBS ...)
find_package(GTest QUIET)
include(GoogleTest)
# rastrules_optimize_as(<target> <flags>): the target's own code compiled with <flags> (e.g.
# -O1) in the optimized builds (RelWithDebInfo, Release), after the build's; empty <flags>
# keep the build's.
function(rastrules_optimize_as target flags)
  if(flags)
    target_compile_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo,Release>:${flags}>)
  endif()
endfunction()

# The tests' own code (examples, properties, their generators) is compiled at -O1 in the
# optimized builds: the code under test (kernel, oracle, io, driver libraries) keeps the
# build's -O2, and the test and property units, heavy with RapidCheck, GoogleTest and CGAL
# templates, compile about a third faster (a property unit: 66 s at -O2, 44 s at -O1), which
# is most of CI's build. RASTRULES_TEST_OPT_FLAGS="" keeps the build's flags.
set(RASTRULES_TEST_OPT_FLAGS "-O1" CACHE STRING
    "Optimization flags of test and property code in RelWithDebInfo and Release builds")
function(rastrules_test_code_options target)
  rastrules_optimize_as(${target} "${RASTRULES_TEST_OPT_FLAGS}")
endfunction()

# The proofs' own code only builds terms for Z3, which does the work: it is compiled at -O0 in
# the optimized builds too (a proof unit: 27.5 s at -O2, 8.8 s at -O0; the proofs were 263 of
# the main build's 2045 CPU-seconds). RASTRULES_PROOF_OPT_FLAGS="" keeps the build's flags.
set(RASTRULES_PROOF_OPT_FLAGS "-O0" CACHE STRING
    "Optimization flags of the Z3 proofs' code in RelWithDebInfo and Release builds")
function(rastrules_proof_code_options target)
  rastrules_optimize_as(${target} "${RASTRULES_PROOF_OPT_FLAGS}")
endfunction()

# The test and property sources of one executable are compiled together, a few to a unit
# (CMake's unity build): each unit parses GoogleTest, RapidCheck and the library headers once
# instead of once a file. RASTRULES_UNITY_TESTS=OFF compiles each file alone (a file that
# does not compile alone is a defect either way: the unity batches change as files come and
# go).
option(RASTRULES_UNITY_TESTS "Compile test and property sources in unity batches" ON)
set(RASTRULES_UNITY_BATCH 4 CACHE STRING "Test and property sources per unity unit")
function(rastrules_test_unity target)
  if(RASTRULES_UNITY_TESTS)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                          UNITY_BUILD_BATCH_SIZE ${RASTRULES_UNITY_BATCH})
  endif()
endfunction()

function(rastrules_add_gtest)
  cmake_parse_arguments(A "" "NAME;AREA;KIND" "SOURCES;LIBS;TEST_PROPERTIES" ${ARGN})
  add_executable(${A_NAME} ${A_SOURCES})
  target_link_libraries(${A_NAME} PRIVATE ${A_LIBS} rastrules_warnings rastrules_sanitize)
  rastrules_test_code_options(${A_NAME})
  rastrules_test_unity(${A_NAME})
  # gtest_discover_tests re-splits a list-valued LABELS, keeping only the first element, so
  # the kind goes on the tests and the area on the directory (CTest adds directory labels to
  # every test defined there; each area has its own folder).
  gtest_discover_tests(${A_NAME}
    DISCOVERY_TIMEOUT 60
    PROPERTIES LABELS "${A_KIND}" ${A_TEST_PROPERTIES})
  set_property(DIRECTORY APPEND PROPERTY LABELS "${A_AREA}")
endfunction()

# rastrules_check_headers(<library> <include dir>): every public header of the library under the
# include dir compiles on its own (includes what it uses), one generated translation unit per
# header in the object library <library>_headers, built with the rest.
# RASTRULES_CHECK_HEADERS=OFF leaves them out: scripts/test's sanitizer build, where the main
# build has checked the same headers already (55 units, about 50 CPU-seconds there).
option(RASTRULES_CHECK_HEADERS "Compile every public header on its own" ON)
function(rastrules_check_headers library include_dir)
  if(NOT RASTRULES_CHECK_HEADERS)
    return()
  endif()
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${include_dir}/*.hpp)
  set(sources)
  foreach(header ${headers})
    file(RELATIVE_PATH rel ${include_dir} ${header})
    string(MAKE_C_IDENTIFIER ${rel} id)
    set(source ${CMAKE_CURRENT_BINARY_DIR}/headers/${id}.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT "#include \"${rel}\" // compiles alone\n")
    list(APPEND sources ${source})
  endforeach()
  add_library(${library}_headers OBJECT ${sources})
  target_link_libraries(${library}_headers PRIVATE ${library} rastrules_warnings)
endfunction()
