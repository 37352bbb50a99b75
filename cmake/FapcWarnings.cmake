# One place for compiler flags shared by every target of the project.
add_library(fapc_flags INTERFACE)
target_compile_options(fapc_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  -Wno-sign-conversion)
if(FAPC_WERROR)
  target_compile_options(fapc_flags INTERFACE -Werror)
endif()
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  # GCC 12 at -O3 reports -Wrestrict inside libstdc++ for ordinary "text" + std::string
  # concatenations (GCC bug 105329, fixed in 13); the warning says nothing about our code.
  target_compile_options(fapc_flags INTERFACE -Wno-restrict)
endif()
if(FAPC_SANITIZE)
  target_compile_options(fapc_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
  target_link_options(fapc_flags INTERFACE -fsanitize=address,undefined)
endif()
if(FAPC_TSAN)
  if(FAPC_SANITIZE)
    message(FATAL_ERROR "FAPC_TSAN and FAPC_SANITIZE cannot be combined: ThreadSanitizer excludes AddressSanitizer")
  endif()
  # The batch runs conversions on several threads (docs/testing.md, "Data races").
  target_compile_options(fapc_flags INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(fapc_flags INTERFACE -fsanitize=thread)
endif()
if(FAPC_FUZZ)
  # libFuzzer needs every library instrumented for coverage; the fuzz programs add the driver.
  # Every sanitizer report is fatal: a UB report that only prints would let the fuzzer run on
  # past the bug it just found.
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()
