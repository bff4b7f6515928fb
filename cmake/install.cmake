# Install rules: what `cmake --install <build> --prefix <dir>` puts under a prefix so that other
# projects can link the verified kernel (design.md, use #1).
#
#   include/rastrules/...            the kernel's public headers (standard library only), and
#                                    with their components the oracle's and io's headers
#   lib/librastrules_kernel.a        rastrules::kernel
#   lib/librastrules_oracle.a        rastrules::oracle  (component oracle: needs CGAL and GMP)
#   lib/librastrules_io.a            rastrules::io      (component io: needs libpng, nlohmann-json)
#   lib/cmake/rastrules/             rastrulesConfig.cmake, its version file and target files
#   lib/pkgconfig/rastrules.pc       the kernel for pkg-config users
#   bin/rastrules                    the command line
#
# The kernel's export set depends on nothing; each component has an export set of its own,
# loaded by rastrulesConfig.cmake only when asked for, after its dependencies are found.

include(CMakePackageConfigHelpers)
set(RASTRULES_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rastrules)

install(TARGETS rastrules_kernel EXPORT rastrulesKernelTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/kernel/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT rastrulesKernelTargets NAMESPACE rastrules:: DESTINATION ${RASTRULES_CMAKE_DIR})

if(TARGET rastrules_oracle)
  install(TARGETS rastrules_oracle EXPORT rastrulesOracleTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/oracle/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT rastrulesOracleTargets NAMESPACE rastrules:: DESTINATION ${RASTRULES_CMAKE_DIR})
endif()
if(TARGET rastrules_io)
  install(TARGETS rastrules_io EXPORT rastrulesIoTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/tools/io/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT rastrulesIoTargets NAMESPACE rastrules:: DESTINATION ${RASTRULES_CMAKE_DIR})
endif()
if(TARGET rastrules)
  install(TARGETS rastrules RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
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
