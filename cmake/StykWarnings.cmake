# Warnings and sanitizers for Styk's own targets (not for third-party code).
add_library(styk_warnings INTERFACE)
target_compile_options(styk_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local)
if(STYK_SANITIZE)
  target_compile_options(styk_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(styk_warnings INTERFACE -fsanitize=address,undefined)
endif()
