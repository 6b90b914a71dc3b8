# Benchmark tools (not tests): deck generators for the scale series. The series itself is
# bench/run_cantilever_series.sh; results and the command that made them are in bench/README.md.
add_executable(make_cantilever make_cantilever.cpp)
target_link_libraries(make_cantilever PRIVATE styk_mesher styk_inp styk_warnings)
add_executable(make_tet_cantilever make_tet_cantilever.cpp)
target_link_libraries(make_tet_cantilever PRIVATE styk_mesher styk_inp styk_elements styk_warnings)
