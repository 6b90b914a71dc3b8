# The desktop program end to end (QTest) under xvfb-run: a QOpenGLWidget needs an X server.
if(NOT TARGET styk_gui_widgets)
  return()
endif()
find_package(Qt6 REQUIRED COMPONENTS Test)
find_program(XVFB_RUN xvfb-run)
add_executable(styk_gui_e2e_test gui_e2e_test.cpp ${PROJECT_SOURCE_DIR}/tests/images/image_compare.cpp)
set_target_properties(styk_gui_e2e_test PROPERTIES AUTOMOC ON)
target_include_directories(styk_gui_e2e_test PRIVATE ${PROJECT_SOURCE_DIR}/tests/images)
target_link_libraries(styk_gui_e2e_test PRIVATE styk_gui_widgets Qt6::Test styk_warnings)
target_compile_definitions(styk_gui_e2e_test PRIVATE
  STYK_SOURCE_DIR="${PROJECT_SOURCE_DIR}" STYK_BINARY_DIR="${PROJECT_BINARY_DIR}"
  STYK_PLUGIN_BUILD_DIR="${STYK_PLUGIN_BUILD_DIR}")
add_dependencies(styk_gui_e2e_test styk_plugins styk)
if(XVFB_RUN)
  add_test(NAME styk_gui_e2e
           COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" $<TARGET_FILE:styk_gui_e2e_test>)
else()
  add_test(NAME styk_gui_e2e COMMAND $<TARGET_FILE:styk_gui_e2e_test>)  # needs a display
endif()
set_tests_properties(styk_gui_e2e PROPERTIES TIMEOUT 300)
