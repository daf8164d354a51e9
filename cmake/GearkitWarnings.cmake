# Warning and sanitizer flags shared by every gearkit target (not by third-party code).
add_library(gearkit_build_flags INTERFACE)
target_compile_options(gearkit_build_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  # GCC 12 reports false -Wrestrict positives inside std::string's operator+ at -O2
  # (GCC bug 105329); they come from libstdc++ headers, not from our code.
  target_compile_options(gearkit_build_flags INTERFACE -Wno-restrict)
endif()
if(GEARKIT_WERROR)
  target_compile_options(gearkit_build_flags INTERFACE -Werror)
endif()
if(GEARKIT_SANITIZE)
  target_compile_options(gearkit_build_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                       -fno-sanitize-recover=undefined)
  target_link_options(gearkit_build_flags INTERFACE -fsanitize=address,undefined)
endif()
