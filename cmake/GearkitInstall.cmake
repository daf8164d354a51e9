# Installs libraries, headers, plugins, the executable and a CMake package, so that
# a third party can write `find_package(gearkit)` and build a plugin of its own.
include(CMakePackageConfigHelpers)
get_property(_libs GLOBAL PROPERTY GEARKIT_LIBRARIES)
install(TARGETS ${_libs} gearkit_build_flags EXPORT gearkitTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS gearkit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT gearkitTargets NAMESPACE gearkit:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/gearkit)
configure_package_config_file(cmake/gearkitConfig.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/gearkitConfig.cmake"
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/gearkit)
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/gearkitConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/gearkitConfig.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/gearkitConfigVersion.cmake"
              cmake/GearkitPlugin.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/gearkit)
