# Every public header (include/ of every library: what `cmake --install` puts in place) includes
# only the C++ standard library and fapc's own public headers, so an installed fapc needs no
# third-party headers (docs/architecture.md, "Public headers and kits"). What the front ends and
# the program share beyond that (libxml2 nodes, JSON values) is in the kits, which are not
# installed. Compiling a header alone cannot catch this: most third-party headers are on the
# compiler's default path.
#   cmake -DSOURCE_DIR=... -P standard_only.cmake
cmake_minimum_required(VERSION 3.25)
set(standard
  algorithm any array atomic barrier bit bitset cassert cctype cerrno cfloat charconv chrono cinttypes
  climits clocale cmath compare complex concepts condition_variable coroutine csignal cstddef
  cstdint cstdio cstdlib cstring ctime cwchar deque exception execution expected filesystem format
  forward_list fstream functional future initializer_list iomanip ios iosfwd iostream istream
  iterator latch limits list locale map memory memory_resource mutex new numbers numeric optional
  ostream queue random ranges ratio regex scoped_allocator semaphore set shared_mutex
  source_location span sstream stack stdexcept stop_token streambuf string string_view
  system_error thread tuple type_traits typeindex typeinfo unordered_map unordered_set utility
  valarray variant vector version)
file(GLOB_RECURSE headers ${SOURCE_DIR}/*/include/*.hpp ${SOURCE_DIR}/*/*/include/*.hpp
     ${SOURCE_DIR}/*/*/*/include/*.hpp)
list(FILTER headers EXCLUDE REGEX "/(build[^/]*|tests|bench)/")
set(problems "")
foreach(header ${headers})
  file(STRINGS ${header} includes REGEX "^[ \t]*#[ \t]*include")
  foreach(line ${includes})
    if(line MATCHES "#[ \t]*include[ \t]*<([^>]+)>")
      set(name ${CMAKE_MATCH_1})
      if(NOT name IN_LIST standard AND NOT name MATCHES "^fapc/")
        string(APPEND problems "  ${header}: <${name}>\n")
      endif()
    elseif(line MATCHES "#[ \t]*include[ \t]*\"([^\"]+)\"")
      set(name ${CMAKE_MATCH_1})
      if(NOT name MATCHES "^fapc/")
        string(APPEND problems "  ${header}: \"${name}\"\n")
      endif()
    endif()
  endforeach()
endforeach()
list(LENGTH headers count)
if(count LESS 50)
  message(FATAL_ERROR "found only ${count} public headers under ${SOURCE_DIR}: the globs are wrong")
endif()
if(problems)
  message(FATAL_ERROR "public headers including what an installed fapc does not have:\n${problems}"
                      "Move the type behind the library or into a kit (docs/architecture.md).")
endif()
message(STATUS "${count} public headers include only the standard library and fapc")
