# ctest sdk_out_of_tree_plugin (tests/sdk/CMakeLists.txt): the commands docs/plugins.md gives for
# building a plug-in outside the Styk tree, run for real against a scratch installation.
#   1. cmake --install <build> --prefix <scratch>/prefix
#   2. cmake -S plugins/template -B <scratch>/tmpl8 -DCMAKE_PREFIX_PATH=<scratch>/prefix,
#      cmake --build, cmake --install (into <prefix>/lib/styk/plugins)
#   3. <prefix>/bin/styk elements and <prefix>/bin/styk-gui --list-elements list TMPL8 from the
#      installed plug-in directory, and the thesis plug-ins from there too (not from the build tree)
#   4. <prefix>/bin/styk solves a deck with TMPL8 elements exactly as with C3D8
# Every step must exit 0; every expected line is asserted. STYK_PLUGIN_PATH is cleared so that
# only the installation's own directory is searched.

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (exit ${rc}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
  set(step_errors "${err}" PARENT_SCOPE)
endfunction()

# Asserts that `listing` (output of an element listing) has a row for `type` whose source is
# `source`, and that nothing was loaded from the build tree.
function(expect_listed program listing type source)
  string(REGEX MATCH "\n${type} [^\n]*" row "\n${listing}")
  if(NOT row)
    message(FATAL_ERROR "${program}: element type ${type} is not listed:\n${listing}")
  endif()
  string(FIND "${row}" "${source}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${program}: ${type} does not come from ${source}:${row}")
  endif()
endfunction()

function(expect_nothing_from_build_tree program listing)
  string(FIND "${listing}" "${PLUGIN_BUILD_DIR}/" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${program} loaded something from the build tree:\n${listing}")
  endif()
endfunction()

unset(ENV{STYK_PLUGIN_PATH})
file(REMOVE_RECURSE ${SCRATCH})
set(prefix ${SCRATCH}/prefix)
set(plugin_dir ${prefix}/${PLUGIN_INSTALL_DIR})

# 1. Install Styk.
run_step("install" ${CMAKE_COMMAND} --install ${STYK_BUILD_DIR} --prefix ${prefix})
foreach(file lib/cmake/Styk/StykConfig.cmake include/styk/plugin/sdk.hpp
             include/styk/core/plugin_api.h include/styk/elements/hex_shapes.hpp bin/styk)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "install: ${prefix}/${file} is missing")
  endif()
endforeach()
# Element formulations are not part of the SDK: a plug-in gets the shape-function library only.
if(EXISTS ${prefix}/include/styk/elements/c3d8.hpp)
  message(FATAL_ERROR "install: the element formulations' headers leaked into the SDK")
endif()

# 2. Build the template plug-in out of tree with find_package(Styk) and install it.
set(launcher "")
if(COMPILER_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER})
endif()
set(sanitize "")
if(SANITIZE_FLAGS)
  set(sanitize "-DCMAKE_CXX_FLAGS=${SANITIZE_FLAGS}" "-DCMAKE_SHARED_LINKER_FLAGS=${SANITIZE_FLAGS}")
endif()
run_step("configure the template" ${CMAKE_COMMAND}
  -S ${STYK_SOURCE_DIR}/plugins/template -B ${SCRATCH}/tmpl8 -G ${GENERATOR}
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher} ${sanitize}
  -DCMAKE_PREFIX_PATH=${prefix})
run_step("build the template" ${CMAKE_COMMAND} --build ${SCRATCH}/tmpl8)
run_step("install the template" ${CMAKE_COMMAND} --install ${SCRATCH}/tmpl8)
file(STRINGS ${SCRATCH}/tmpl8/install_manifest.txt installed_files)
if(NOT installed_files STREQUAL "${plugin_dir}/libstyk_tmpl8.so")
  message(FATAL_ERROR "the template installed ${installed_files}, not ${plugin_dir}/libstyk_tmpl8.so")
endif()
if(NOT EXISTS ${plugin_dir}/libstyk_tmpl8.so)
  message(FATAL_ERROR "the template was not installed into ${plugin_dir}")
endif()
# The ABI entry point is the plug-in's one exported Styk symbol: the SDK's archives stay hidden
# inside it. The only other dynamic symbols are weak instantiations of standard-library templates
# (namespace std, which libstdc++ declares with default visibility), as for the in-tree plug-ins.
if(NM)
  run_step("nm" ${NM} -D --defined-only ${plugin_dir}/libstyk_tmpl8.so)
  string(REGEX MATCHALL "[^\n]+" symbols "${step_output}")
  set(entry_found FALSE)
  foreach(line IN LISTS symbols)
    if(line MATCHES " T styk_plugin_register$")
      set(entry_found TRUE)
    elseif(NOT line MATCHES " W _ZN?K?St[^ ]*$")
      message(FATAL_ERROR "the plug-in exports ${line}:\n${step_output}")
    endif()
  endforeach()
  if(NOT entry_found)
    message(FATAL_ERROR "the plug-in does not export styk_plugin_register:\n${step_output}")
  endif()
endif()

# 3. The installed programs find it in the installation's plug-in directory.
run_step("styk elements" ${prefix}/bin/styk elements)
if(NOT step_errors STREQUAL "")
  message(FATAL_ERROR "styk elements warned:\n${step_errors}")
endif()
expect_listed("styk elements" "${step_output}" TMPL8 ${plugin_dir}/libstyk_tmpl8.so)
expect_listed("styk elements" "${step_output}" C3D14 ${plugin_dir}/libstyk_c3d14.so)
expect_listed("styk elements" "${step_output}" C3D8 built-in)
expect_nothing_from_build_tree("styk elements" "${step_output}")

if(GUI_PROGRAM)
  run_step("styk-gui --list-elements" ${prefix}/bin/${GUI_PROGRAM} --list-elements)
  if(NOT step_errors STREQUAL "")
    message(FATAL_ERROR "styk-gui --list-elements warned:\n${step_errors}")
  endif()
  expect_listed("styk-gui" "${step_output}" TMPL8 ${plugin_dir}/libstyk_tmpl8.so)
  expect_listed("styk-gui" "${step_output}" C3D28 ${plugin_dir}/libstyk_c3d28.so)
  expect_nothing_from_build_tree("styk-gui" "${step_output}")
endif()
# 4. The out-of-tree TMPL8 computes: the installed styk solves the SPEC 2.1 cantilever (6x1 mesh,
# samples/) once with C3D8 and once with TYPE=TMPL8. The template is C3D8's formulation compiled
# in the plug-in, so the two .dat reports (tip displacements, root reactions) must be identical,
# byte for byte (tolerance: none).
file(READ ${STYK_SOURCE_DIR}/samples/spec-2.1-cantilever-c3d8-6x1.inp deck)
string(REPLACE "*ELEMENT, TYPE=C3D8\n" "*ELEMENT, TYPE=TMPL8\n" tmpl8_deck "${deck}")
if(tmpl8_deck STREQUAL deck)
  message(FATAL_ERROR "the cantilever deck has no *ELEMENT, TYPE=C3D8 line to replace")
endif()
file(MAKE_DIRECTORY ${SCRATCH}/solve)
file(WRITE ${SCRATCH}/solve/c3d8.inp "${deck}")
file(WRITE ${SCRATCH}/solve/tmpl8.inp "${tmpl8_deck}")
foreach(model c3d8 tmpl8)
  run_step("styk solve ${model}.inp" ${prefix}/bin/styk solve ${SCRATCH}/solve/${model}.inp
    -o ${SCRATCH}/solve -q)
endforeach()
file(READ ${SCRATCH}/solve/c3d8.dat c3d8_report)
file(READ ${SCRATCH}/solve/tmpl8.dat tmpl8_report)
if(NOT c3d8_report MATCHES "displacements" OR NOT tmpl8_report STREQUAL c3d8_report)
  message(FATAL_ERROR "TMPL8 and C3D8 reports differ:\n${c3d8_report}\n---\n${tmpl8_report}")
endif()

message(STATUS "sdk_out_of_tree_plugin: TMPL8 built against ${prefix} and loaded by the installed programs")
