# The `styk` command-line program. CLI11 is confined to main.cpp (it is slow to compile).
add_executable(styk
  src/main.cpp
  src/exit_codes.cpp
  src/stderr_progress.cpp
  src/json_progress.cpp
  src/command_solve.cpp
  src/mpi_launcher.cpp
  src/command_info.cpp
  src/command_export.cpp
  src/command_import.cpp
  src/command_check.cpp
  src/command_elements.cpp
  src/atomic_file.cpp
  src/registry_setup.cpp
  src/output_paths.cpp
  src/command_mesh.cpp
  src/command_verify.cpp
  src/command_study.cpp
)
target_include_directories(styk PRIVATE src)
# nlohmann-json: the JSON lines of `styk solve --progress json` (json_progress.cpp only).
find_package(nlohmann_json 3 REQUIRED)
target_link_libraries(styk PRIVATE nlohmann_json::nlohmann_json)
target_link_libraries(styk PRIVATE styk_solver styk_inp styk_io styk_elements styk_mesher styk_studies styk_gmsh CLI11::CLI11 fmt::fmt
  styk_warnings)
# `styk render` needs the OSMesa renderer (STYK_OSMESA, on by default).
if(TARGET styk_render_osmesa)
  target_sources(styk PRIVATE src/command_render.cpp)
  target_link_libraries(styk PRIVATE styk_render_osmesa)
  target_compile_definitions(styk PRIVATE STYK_WITH_RENDER)
endif()
install(TARGETS styk RUNTIME DESTINATION bin)
# Element registry: styk_element_setup (built-ins, then the plug-ins of STYK_PLUGIN_PATH and of
# the installation or the build tree); build the plug-ins with the program.
target_link_libraries(styk PRIVATE styk_element_setup)
add_dependencies(styk styk_plugins)
