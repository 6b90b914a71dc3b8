# The desktop program end to end (QTest) under xvfb-run: a QOpenGLWidget needs an X server.
if(NOT TARGET styk_gui_widgets)
  return()
endif()
find_package(Qt6 REQUIRED COMPONENTS Test)
add_executable(styk_gui_e2e_test gui_e2e_test.cpp ${PROJECT_SOURCE_DIR}/tests/images/image_compare.cpp)
set_target_properties(styk_gui_e2e_test PROPERTIES AUTOMOC ON)
target_include_directories(styk_gui_e2e_test PRIVATE ${PROJECT_SOURCE_DIR}/tests/images)
target_link_libraries(styk_gui_e2e_test PRIVATE styk_gui_widgets Qt6::Test styk_warnings)
target_compile_definitions(styk_gui_e2e_test PRIVATE
  STYK_SOURCE_DIR="${PROJECT_SOURCE_DIR}" STYK_BINARY_DIR="${PROJECT_BINARY_DIR}"
  STYK_PLUGIN_BUILD_DIR="${STYK_PLUGIN_BUILD_DIR}")
add_dependencies(styk_gui_e2e_test styk_plugins styk)
# xvfb-run is looked up on PATH when the test runs, not cached at configure time: the build tree
# may be configured before `scripts/install-deps.sh --test` installs it (run-sample.sh first).
add_test(NAME styk_gui_e2e
         COMMAND xvfb-run -a -s "-screen 0 1600x1200x24" $<TARGET_FILE:styk_gui_e2e_test>)
set_tests_properties(styk_gui_e2e PROPERTIES TIMEOUT 300)

# Issue 7: the SPEC §4.2 shrink fit built from an empty window through the dialogs, solved, and
# its contact pressure checked and charted (STYK_GUI_SCREENSHOTS=dir writes the docs' pictures).
add_executable(styk_gui_shrink_fit_e2e_test gui_shrink_fit_e2e_test.cpp)
set_target_properties(styk_gui_shrink_fit_e2e_test PROPERTIES AUTOMOC ON)
target_link_libraries(styk_gui_shrink_fit_e2e_test PRIVATE styk_gui_widgets Qt6::Test styk_warnings)
target_compile_definitions(styk_gui_shrink_fit_e2e_test PRIVATE
  STYK_PLUGIN_BUILD_DIR="${STYK_PLUGIN_BUILD_DIR}")
add_dependencies(styk_gui_shrink_fit_e2e_test styk_plugins styk)
add_test(NAME styk_gui_shrink_fit_e2e
         COMMAND xvfb-run -a -s "-screen 0 1600x1200x24" $<TARGET_FILE:styk_gui_shrink_fit_e2e_test>)
set_tests_properties(styk_gui_shrink_fit_e2e PROPERTIES TIMEOUT 300)

# Round 2: the SPEC §6.2 cylinder wall as a steady heat model from an empty window, a boundary
# condition edited in the model tree, the solve and the probe on r = 2.5 against T(r).
add_executable(styk_gui_heat_edit_e2e_test gui_heat_edit_e2e_test.cpp)
set_target_properties(styk_gui_heat_edit_e2e_test PROPERTIES AUTOMOC ON)
target_link_libraries(styk_gui_heat_edit_e2e_test PRIVATE styk_gui_widgets Qt6::Test styk_warnings)
target_compile_definitions(styk_gui_heat_edit_e2e_test PRIVATE
  STYK_PLUGIN_BUILD_DIR="${STYK_PLUGIN_BUILD_DIR}")
add_dependencies(styk_gui_heat_edit_e2e_test styk_plugins styk)
add_test(NAME styk_gui_heat_edit_e2e
         COMMAND xvfb-run -a -s "-screen 0 1600x1200x24" $<TARGET_FILE:styk_gui_heat_edit_e2e_test>)
set_tests_properties(styk_gui_heat_edit_e2e PROPERTIES TIMEOUT 300)

# Issue 12: a study's CSV as interactive charts (File > Open study charts).
add_executable(styk_gui_study_charts_e2e_test gui_study_charts_e2e_test.cpp)
set_target_properties(styk_gui_study_charts_e2e_test PROPERTIES AUTOMOC ON)
target_link_libraries(styk_gui_study_charts_e2e_test PRIVATE styk_gui_widgets Qt6::Test styk_warnings)
target_compile_definitions(styk_gui_study_charts_e2e_test PRIVATE
  STYK_SOURCE_DIR="${PROJECT_SOURCE_DIR}" STYK_BINARY_DIR="${PROJECT_BINARY_DIR}"
  STYK_PLUGIN_BUILD_DIR="${STYK_PLUGIN_BUILD_DIR}")
add_dependencies(styk_gui_study_charts_e2e_test styk_plugins)
add_test(NAME styk_gui_study_charts_e2e
         COMMAND xvfb-run -a -s "-screen 0 1600x1200x24" $<TARGET_FILE:styk_gui_study_charts_e2e_test>)
set_tests_properties(styk_gui_study_charts_e2e PROPERTIES TIMEOUT 300)
