# One place for compiler flags shared by every target of the project.
add_library(fapc_flags INTERFACE)
target_compile_options(fapc_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  -Wno-sign-conversion)
if(FAPC_WERROR)
  target_compile_options(fapc_flags INTERFACE -Werror)
endif()
if(FAPC_SANITIZE)
  target_compile_options(fapc_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
  target_link_options(fapc_flags INTERFACE -fsanitize=address,undefined)
endif()
if(FAPC_FUZZ)
  # libFuzzer needs every library instrumented for coverage; the fuzz programs add the driver.
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
