# For out-of-tree plugins: gearkit_add_external_plugin(<target> <sources...>)
# builds a MODULE that the gearkit executable can load (put its folder in GEARKIT_PLUGIN_PATH).
function(gearkit_add_external_plugin target)
  add_library(${target} MODULE ${ARGN})
  set_target_properties(${target} PROPERTIES PREFIX "" CXX_STANDARD 20 CXX_STANDARD_REQUIRED ON)
  target_link_libraries(${target} PRIVATE gearkit::kin gearkit::io)
endfunction()
