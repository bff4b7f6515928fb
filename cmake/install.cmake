# Install rules: what `cmake --install <build> --prefix <dir>` puts under a prefix so that other
# projects can link the verified kernel (design.md, use #1).
#
#   include/rastrules/...            the kernel's public headers (standard library and Boost headers), and
#                                    with their components the oracle's and io's headers
#   lib/librastrules_kernel.a        rastrules::kernel
#   lib/librastrules_oracle.a        rastrules::oracle  (component oracle: needs CGAL and GMP)
#   lib/librastrules_check.a         rastrules::check   (component check: kernel against oracle)
#   lib/librastrules_io.a            rastrules::io      (component io: needs libpng, nlohmann-json)
#   lib/librastrules_c.a             rastrules::c       (component c: the C API, rastrules/rastrules.h;
#                                                        needs io)
#   lib/cmake/rastrules/             rastrulesConfig.cmake, its version file and target files
#   lib/pkgconfig/rastrules.pc       the kernel for pkg-config users
#   lib/pkgconfig/rastrules-c.pc     the C API for pkg-config users (C compilers)
#   bin/rastrules                    the command line
#   lib/python3.X/site-packages/rastrules/  the Python module (python/CMakeLists.txt), when built
#
# The kernel's export set depends on nothing; each component has an export set of its own,
# loaded by rastrulesConfig.cmake only when asked for, after its dependencies are found.

include(CMakePackageConfigHelpers)
set(RASTRULES_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rastrules)

# Installs a library, its headers (further arguments: install(DIRECTORY) options, such as
# headers to leave out) and its export set rastrules<Export>Targets.
function(rastrules_install_part target export include_dir)
  install(TARGETS ${target} EXPORT rastrules${export}Targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${include_dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${ARGN})
  install(EXPORT rastrules${export}Targets NAMESPACE rastrules:: DESTINATION ${RASTRULES_CMAKE_DIR})
endfunction()

rastrules_install_part(rastrules_kernel Kernel ${PROJECT_SOURCE_DIR}/kernel/include)
if(TARGET rastrules_oracle)
  rastrules_install_part(rastrules_oracle Oracle ${PROJECT_SOURCE_DIR}/oracle/include)
endif()
if(TARGET rastrules_check)
  rastrules_install_part(rastrules_check Check ${PROJECT_SOURCE_DIR}/check/include)
endif()
if(TARGET rastrules_io)
  # glyph.hpp belongs to rastrules_glyph (FreeType), which is not installed.
  rastrules_install_part(rastrules_io Io ${PROJECT_SOURCE_DIR}/tools/io/include
                         PATTERN glyph.hpp EXCLUDE)
endif()
if(TARGET rastrules_c)
  rastrules_install_part(rastrules_c C ${PROJECT_SOURCE_DIR}/capi/include)
endif()
if(TARGET rastrules)
  # Both programs in one directory: rastrules runs rastrules-full beside it (SCENE.CLI.FRONT).
  install(TARGETS rastrules rastrules_full RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rastrulesConfig.cmake.in
  ${PROJECT_BINARY_DIR}/install/rastrulesConfig.cmake
  INSTALL_DESTINATION ${RASTRULES_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/install/rastrulesConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/install/rastrulesConfig.cmake
              ${PROJECT_BINARY_DIR}/install/rastrulesConfigVersion.cmake
        DESTINATION ${RASTRULES_CMAKE_DIR})

# The prefix relative to the .pc file, so that `cmake --install --prefix` anywhere stays right.
file(RELATIVE_PATH RASTRULES_PC_TO_PREFIX /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)
configure_file(${CMAKE_CURRENT_LIST_DIR}/rastrules.pc.in ${PROJECT_BINARY_DIR}/install/rastrules.pc
               @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/install/rastrules.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(TARGET rastrules_c)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/rastrules-c.pc.in
                 ${PROJECT_BINARY_DIR}/install/rastrules-c.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/install/rastrules-c.pc
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()

# The licence travels with the installed headers and libraries.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
