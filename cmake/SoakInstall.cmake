# `cmake --install BUILD --prefix P`: programs in P/bin, the core library and
# the plugins in P/lib (P/lib/soak-plugins), headers in P/include/soak, docs
# and scenes in P/share/soak, and the CMake package in P/lib/cmake/Soak
# (find_package(Soak): Soak::core, Soak::test_support, soak_add_plugin).
# The same rules make the Debian package (cpack -G DEB).
include(CMakePackageConfigHelpers)
set(SOAK_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Soak)
install(EXPORT SoakTargets NAMESPACE Soak:: DESTINATION ${SOAK_CMAKE_DIR} COMPONENT sdk)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/SoakConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/SoakConfig.cmake INSTALL_DESTINATION ${SOAK_CMAKE_DIR}
                              PATH_VARS CMAKE_INSTALL_LIBDIR)
# A plugin must be built against the very version that loads it (the
# loader refuses any other), so the package matches the exact version only.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/SoakConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY ExactVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/SoakConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/SoakConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/SoakPluginFunctions.cmake
        DESTINATION ${SOAK_CMAKE_DIR} COMPONENT sdk)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/Scenes DESTINATION ${CMAKE_INSTALL_DATADIR}/soak COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/Doc/ DESTINATION ${CMAKE_INSTALL_DATADIR}/soak/doc COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/soak/doc COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/Demos/plugin-template DESTINATION ${CMAKE_INSTALL_DATADIR}/soak COMPONENT sdk)

# Debian package: the runtime libraries it needs are found by dpkg-shlibdeps
# from the installed binaries.
set(CPACK_PACKAGE_NAME soak)
set(CPACK_PACKAGE_VENDOR "Soak")
set(CPACK_PACKAGE_CONTACT "Soak developers <soak@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
include(CPack)
