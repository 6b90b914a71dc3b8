# The Qt6 part of styk-gui (included from gui/app/CMakeLists.txt).
find_package(Qt6 REQUIRED COMPONENTS Widgets OpenGL OpenGLWidgets Charts)

add_library(styk_gui_widgets STATIC
  src/gl_view.cpp
  src/form_dialog.cpp
  src/model_dialogs.cpp
  src/dialog_fields.cpp
  src/revolve_dialog.cpp
  src/geometry_dialogs.cpp
  src/interaction_dialogs.cpp
  src/load_dialogs.cpp
  src/entry_dialogs.cpp
  src/model_tree.cpp
  src/results_panel.cpp
  src/path_chart.cpp
  src/study_chart_window.cpp
  src/solve_runner.cpp
  src/child_process_solve.cpp
  src/main_window.cpp
  src/main_window_menus.cpp
  src/main_window_autosave.cpp
)
set_target_properties(styk_gui_widgets PROPERTIES AUTOMOC ON)
target_include_directories(styk_gui_widgets PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(styk_gui_widgets
  PUBLIC styk_gui_session styk_study_results Qt6::Widgets Qt6::OpenGL Qt6::OpenGLWidgets Qt6::Charts
  PRIVATE styk_charts styk_inp styk_io styk_mesher styk_warnings)
# Solving runs `styk solve` as a child process; in the build tree it is found here (cli/ is
# added after gui/, so no if(TARGET styk): the generator expression resolves at generation).
target_compile_definitions(styk_gui_widgets PRIVATE STYK_CLI_BUILD_PATH="$<TARGET_FILE:styk>")

add_executable(styk-gui src/main.cpp)
target_link_libraries(styk-gui PRIVATE styk_gui_widgets styk_gui_session styk_warnings)
add_dependencies(styk-gui styk_plugins styk)
install(TARGETS styk-gui RUNTIME DESTINATION bin)
