# styk_add_element_plugin(<target> SOURCES ... [LIBS ...] [OUTPUT_DIRECTORY dir] [NO_INSTALL])
#
# Builds the element plug-in lib<target>.so against the Styk plug-in SDK. The same function serves
# the plug-ins of the Styk source tree and plug-ins built outside it against an installed Styk
# (find_package(Styk), docs/plugins.md). It reads three variables of the caller:
#   STYK_PLUGIN_SDK_TARGET       the SDK target (styk_plugin_sdk in the tree, Styk::plugin_sdk
#                                from the installed package)
#   STYK_PLUGIN_DESTINATION      where `cmake --install` puts the plug-in: the plug-in directory
#                                the Styk programs search (<prefix>/lib/styk/plugins)
#   STYK_PLUGIN_OUTPUT_DIRECTORY where the build puts it unless OUTPUT_DIRECTORY says otherwise
#                                (empty: the current binary directory)
#
# The SDK's static archives (styk_core, styk_shapes) are linked INTO the plug-in, which therefore
# carries its own copy of the TElement base-class code and needs nothing from the program that
# loads it (checked by --no-undefined). --exclude-libs keeps those copies out of the dynamic symbol
# table, so only styk_plugin_register is exported and nothing is interposed between host and
# plug-in.
function(styk_add_element_plugin target)
  cmake_parse_arguments(ARG "NO_INSTALL" "OUTPUT_DIRECTORY" "SOURCES;LIBS" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "styk_add_element_plugin(${target}): no SOURCES given")
  endif()
  if(NOT ARG_OUTPUT_DIRECTORY)
    set(ARG_OUTPUT_DIRECTORY ${STYK_PLUGIN_OUTPUT_DIRECTORY})
  endif()
  add_library(${target} MODULE ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE ${STYK_PLUGIN_SDK_TARGET} ${ARG_LIBS})
  target_link_options(${target} PRIVATE "LINKER:--exclude-libs,ALL" "LINKER:--no-undefined")
  set_target_properties(${target} PROPERTIES
    PREFIX "lib"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIRECTORY})
  endif()
  if(NOT ARG_NO_INSTALL)
    install(TARGETS ${target} LIBRARY DESTINATION ${STYK_PLUGIN_DESTINATION})
  endif()
endfunction()
