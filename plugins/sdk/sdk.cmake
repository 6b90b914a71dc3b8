# Installs the plug-in SDK (included from plugins/CMakeLists.txt): headers, the static archives
# styk_core and styk_shapes, and the CMake package Styk (StykConfig.cmake, exported targets
# Styk::core, Styk::shapes, Styk::plugin_sdk, and styk_add_element_plugin()), so that
# find_package(Styk) works against <prefix> and plug-ins are built outside this tree.
include(CMakePackageConfigHelpers)

set(STYK_CMAKE_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Styk)

install(TARGETS styk_core styk_shapes styk_plugin_sdk EXPORT StykTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY
    ${PROJECT_SOURCE_DIR}/core/include/
    ${CMAKE_CURRENT_SOURCE_DIR}/sdk/include/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${STYK_SHAPE_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/styk/elements)
install(EXPORT StykTargets NAMESPACE Styk:: DESTINATION ${STYK_CMAKE_PACKAGE_DIR})

# The ABI version the installed headers declare, for the package's users (read from the header,
# so it cannot drift).
file(STRINGS ${PROJECT_SOURCE_DIR}/core/include/styk/core/plugin_api.h abi_line
  REGEX "^#define STYK_PLUGIN_ABI_VERSION ")
string(REGEX REPLACE "^#define STYK_PLUGIN_ABI_VERSION ([0-9]+)u.*" "\\1" STYK_PLUGIN_ABI_VERSION
  "${abi_line}")
configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/sdk/StykConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/StykConfig.cmake
  INSTALL_DESTINATION ${STYK_CMAKE_PACKAGE_DIR}
  PATH_VARS STYK_PLUGIN_INSTALL_DIR)
# The ABI changes with the minor version at most, and the loader's handshake rejects a mismatch.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/StykConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES
    ${CMAKE_CURRENT_BINARY_DIR}/StykConfig.cmake
    ${CMAKE_CURRENT_BINARY_DIR}/StykConfigVersion.cmake
    ${CMAKE_CURRENT_SOURCE_DIR}/sdk/cmake/StykPluginFunctions.cmake
  DESTINATION ${STYK_CMAKE_PACKAGE_DIR})
