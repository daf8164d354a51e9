# Helpers that keep every library, plugin and test suite built the same way.
# Sources are globbed (CONFIGURE_DEPENDS) so that adding a file to src/ needs no CMake edit.

# gearkit_add_library(<name> DEPS <public deps...> [PRIVATE <private deps...>])
#   Builds lib<name>/src/*.cpp as the shared library gearkit_<name> (alias gearkit::<name>)
#   with public headers in lib<name>/include.
function(gearkit_add_library name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE" ${ARGN})
  file(GLOB _src CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp")
  add_library(gearkit_${name} SHARED ${_src})
  add_library(gearkit::${name} ALIAS gearkit_${name})
  set_target_properties(gearkit_${name} PROPERTIES EXPORT_NAME ${name}
                        VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
                        INSTALL_RPATH "$ORIGIN")  # the other gearkit libraries sit next to it
  target_include_directories(gearkit_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(gearkit_${name} PUBLIC ${ARG_DEPS} PRIVATE gearkit_build_flags ${ARG_PRIVATE})
  # Calls inside a library to its own functions bind at link time, not through the dynamic
  # linker: a third fewer relocations to resolve at start-up (every command loads all the
  # libraries with RTLD_NOW; `gearkit cam` ~1.5 ms faster, docs/benchmarks.md). Data (static
  # locals of inline functions, typeinfo) still binds to one copy; only the address of an inline
  # function taken in two libraries may differ, which gearkit never compares.
  target_link_options(gearkit_${name} PRIVATE -Wl,-Bsymbolic-functions)
  set_property(GLOBAL APPEND PROPERTY GEARKIT_LIBRARIES gearkit_${name})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# gearkit_add_plugin(<name> DEPS <deps...>)
#   (links gearkit::plugin and gearkit::io; a plugin with element types adds gearkit::mechanism)
#   Builds plugins/<name>/*.cpp as the MODULE gearkit_plugin_<name>, placed in lib/gearkit/plugins
#   of the build tree and of the install (where the executable looks, see default_plugin_locations).
function(gearkit_add_plugin name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB _src CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  add_library(gearkit_plugin_${name} MODULE ${_src})
  set_target_properties(gearkit_plugin_${name} PROPERTIES
    PREFIX "" OUTPUT_NAME "gearkit-${name}"
    LIBRARY_OUTPUT_DIRECTORY "${GEARKIT_PLUGIN_BUILD_DIR}"
    INSTALL_RPATH "$ORIGIN/../..")  # lib/gearkit/plugins -> lib
  target_link_libraries(gearkit_plugin_${name} PRIVATE gearkit::plugin gearkit::io gearkit_build_flags ${ARG_DEPS})
  target_link_options(gearkit_plugin_${name} PRIVATE -Wl,-Bsymbolic-functions)  # as gearkit_add_library
  set_property(GLOBAL APPEND PROPERTY GEARKIT_PLUGINS gearkit_plugin_${name})
  install(TARGETS gearkit_plugin_${name} LIBRARY DESTINATION ${GEARKIT_PLUGIN_INSTALL_DIR})
endfunction()

# gearkit_add_test_suite(<name> DEPS <deps...>)
#   Builds tests/<name>/*.cpp into one GoogleTest executable registered with ctest.
function(gearkit_add_test_suite name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB _src CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp")
  if(NOT _src)
    return()
  endif()
  if(GEARKIT_SANITIZE)
    list(APPEND _src "${PROJECT_SOURCE_DIR}/cli/lsan_suppressions.cpp")
  endif()
  add_executable(test_${name} ${_src})
  if(GEARKIT_SANITIZE)
    target_compile_definitions(test_${name} PRIVATE GEARKIT_SANITIZED=1)  # for tests that cannot run under ASan
  endif()
  target_link_libraries(test_${name} PRIVATE GTest::gtest_main gearkit_build_flags ${ARG_DEPS})
  target_include_directories(test_${name} PRIVATE "${PROJECT_SOURCE_DIR}/tests/support")
  target_compile_definitions(test_${name} PRIVATE
    GEARKIT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    GEARKIT_BINARY_DIR="${PROJECT_BINARY_DIR}"
    GEARKIT_EXE="$<TARGET_FILE:gearkit>")
  gtest_discover_tests(test_${name} DISCOVERY_MODE PRE_TEST PROPERTIES LABELS ${name})
endfunction()
