# Warnings and sanitizers for Styk's own targets (not for third-party code).
add_library(styk_warnings INTERFACE)
target_compile_options(styk_warnings INTERFACE -Wall -Wextra -Wpedantic
  $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local>)
if(STYK_SANITIZE)
  target_compile_options(styk_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(styk_warnings INTERFACE -fsanitize=address,undefined)
endif()
# The fuzzing build (STYK_FUZZ, scripts/fuzz.sh; clang only): Styk's code instrumented for
# libFuzzer's coverage and checked by ASan and UBSan (any undefined behaviour stops the run).
if(STYK_FUZZ)
  target_compile_options(styk_warnings INTERFACE -fsanitize=fuzzer-no-link,address,undefined
    -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_link_options(styk_warnings INTERFACE -fsanitize=address,undefined)
endif()
