# For out-of-tree plugins: gearkit_add_external_plugin(<target> <sources...>)
# builds a MODULE that the gearkit executable can load (put its folder in GEARKIT_PLUGIN_PATH).
# It links the plugin interface and gearkit::io (reports, options, errors); a plugin that adds
# element types for mechanism files also links gearkit::mechanism (and gearkit::elements for the
# shipped element builders).
function(gearkit_add_external_plugin target)
  add_library(${target} MODULE ${ARGN})
  set_target_properties(${target} PROPERTIES PREFIX "" CXX_STANDARD 20 CXX_STANDARD_REQUIRED ON)
  target_link_libraries(${target} PRIVATE gearkit::plugin gearkit::io)
endfunction()
