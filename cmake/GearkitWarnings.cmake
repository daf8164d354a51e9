# Warning and sanitizer flags shared by every gearkit target (not by third-party code).
add_library(gearkit_build_flags INTERFACE)
target_compile_options(gearkit_build_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local)
if(GEARKIT_WERROR)
  target_compile_options(gearkit_build_flags INTERFACE -Werror)
endif()
if(GEARKIT_SANITIZE)
  target_compile_options(gearkit_build_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                       -fno-sanitize-recover=undefined)
  target_link_options(gearkit_build_flags INTERFACE -fsanitize=address,undefined)
endif()
