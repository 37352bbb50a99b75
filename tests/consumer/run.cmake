# One consumer test (tests/CMakeLists.txt): install the build into a fresh prefix, configure and
# build tests/consumer/<CONSUMER> against that prefix alone, and run its program PROGRAM with
# ARGS (@WORK@ in them stands for WORK_DIR).
# For the codec consumer libxml2 and Xerces-C are hidden from find_package, and a project asking
# for the xml component must then fail: the codec's package needs neither library.
#   cmake -DCONSUMER=codec -DPROGRAM=fap_roundtrip -DBUILD_DIR=... -DSOURCE_DIR=...
#         -DWORK_DIR=... -DGENERATOR=...
#         -DCXX_COMPILER=... [-DCXX_LAUNCHER=...] [-DSAME_AS_FAPC=compile] "-DARGS=..." -P run.cmake
foreach(required CONSUMER PROGRAM BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "run.cmake needs -D${required}=...")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run("installing the build" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

set(configure_args -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
if(CXX_LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
if(CONSUMER STREQUAL "codec")
  set(hide_xml -DCMAKE_DISABLE_FIND_PACKAGE_LibXml2=TRUE -DCMAKE_DISABLE_FIND_PACKAGE_XercesC=TRUE)
  list(APPEND configure_args ${hide_xml})

  # The control: with the same settings a project that needs the xml component is refused, so the
  # codec consumer's success below means the codec really does without them.
  file(WRITE ${WORK_DIR}/needs-xml/CMakeLists.txt
    "cmake_minimum_required(VERSION 3.25)\nproject(needs_xml LANGUAGES CXX)\n"
    "find_package(fapc REQUIRED COMPONENTS xml)\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/needs-xml -B ${WORK_DIR}/needs-xml/build
                          ${configure_args}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(status EQUAL 0 OR NOT err MATCHES "LibXml2")
    message(FATAL_ERROR "find_package(fapc COMPONENTS xml) with libxml2 hidden should fail "
                        "naming LibXml2 (status ${status}):\n${out}\n${err}")
  endif()
endif()

set(consumer_build ${WORK_DIR}/build)
run("configuring tests/consumer/${CONSUMER}"
    ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/${CONSUMER} -B ${consumer_build} ${configure_args})
run("building tests/consumer/${CONSUMER}" ${CMAKE_COMMAND} --build ${consumer_build})

set(program_path ${consumer_build}/${PROGRAM})
string(REPLACE "@WORK@" "${WORK_DIR}" ARGS "${ARGS}")
run("running ${program_path}" ${program_path} ${ARGS})
message(STATUS "${run_output}")

# The codec consumer once more, built by pkg-config alone (docs/building.md, "pkg-config"), and
# what else the install puts in place: the licence, the docs, the man page and the completions.
if(CONSUMER STREQUAL "codec")
  file(GLOB_RECURSE pc_files ${prefix}/*/fapc-codec.pc)
  if(NOT pc_files)
    message(FATAL_ERROR "no fapc-codec.pc under ${prefix}")
  endif()
  list(GET pc_files 0 pc_file)
  get_filename_component(pc_dir ${pc_file} DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} ${pc_dir})
  set(ENV{PKG_CONFIG_LIBDIR} ${pc_dir}:/usr/lib/x86_64-linux-gnu/pkgconfig:/usr/lib/pkgconfig:/usr/share/pkgconfig)
  run("pkg-config --cflags --static --libs fapc-codec" pkg-config --cflags --static --libs fapc-codec)
  separate_arguments(pc_flags UNIX_COMMAND "${run_output}")
  if(NOT run_output MATCHES "-lfapc_codec" OR NOT run_output MATCHES "-lz")
    message(FATAL_ERROR "pkg-config --static --libs fapc-codec should name fapc_codec and zlib: ${run_output}")
  endif()
  run("pkg-config --print-requires-private fapc-xml" pkg-config --print-requires-private fapc-xml)
  if(NOT run_output MATCHES "xerces-c")
    message(FATAL_ERROR "fapc-xml.pc should require xerces-c privately: ${run_output}")
  endif()
  set(pc_program ${WORK_DIR}/fap_roundtrip_pkgconfig)
  run("building tests/consumer/codec with pkg-config" ${CXX_COMPILER}
      ${SOURCE_DIR}/tests/consumer/codec/fap_roundtrip.cpp -o ${pc_program} ${pc_flags})
  set(pc_args ${ARGS})
  string(REPLACE "@WORK@" "${WORK_DIR}" pc_args "${pc_args}")
  list(TRANSFORM pc_args REPLACE "\\.fba$" "-pkgconfig.fba")
  # pkg-config gives no run path: a shared build's libraries are found as an installed system's
  # would be through ld.so, here through LD_LIBRARY_PATH.
  get_filename_component(pc_libdir ${pc_dir} DIRECTORY)
  set(ENV{LD_LIBRARY_PATH} ${pc_libdir})
  run("running ${pc_program}" ${pc_program} ${pc_args})
  unset(ENV{LD_LIBRARY_PATH})

  foreach(installed LICENSE COPYING.LGPL-2.1 README.md docs/json.md docs/json/info.schema.json)
    if(NOT EXISTS ${prefix}/share/doc/fapc/${installed})
      message(FATAL_ERROR "cmake --install did not install ${installed}")
    endif()
  endforeach()
  # The man page and completions come with the command-line work (issue 18a): once the build
  # installs them (its tools/CMakeLists.txt names MANDIR) they must be there and work.
  file(READ ${SOURCE_DIR}/tools/CMakeLists.txt tools_cmake)
  if(tools_cmake MATCHES "CMAKE_INSTALL_MANDIR")
    foreach(installed share/man/man1/fapc.1 share/bash-completion/completions/fapc share/zsh/vendor-completions/_fapc)
      if(NOT EXISTS ${prefix}/${installed})
        message(FATAL_ERROR "cmake --install did not install ${installed}")
      endif()
    endforeach()
    set(ENV{MANPATH} ${prefix}/share/man)
    set(ENV{MANWIDTH} 80)
    run("MANPATH=${prefix}/share/man man fapc" man -P cat fapc)
    if(NOT run_output MATCHES "fapc")
      message(FATAL_ERROR "man fapc shows no page:\n${run_output}")
    endif()
    run("man -l fapc.1" man -P cat -l ${prefix}/share/man/man1/fapc.1)
    # The bash completion loads and completes fapc; the zsh one is a function file (#compdef).
    run("loading the bash completion" bash -c
        "source '${prefix}/share/bash-completion/completions/fapc' && complete -p fapc")
    file(READ ${prefix}/share/zsh/vendor-completions/_fapc zsh_completion)
    if(NOT zsh_completion MATCHES "^#compdef fapc")
      message(FATAL_ERROR "share/zsh/vendor-completions/_fapc does not start with '#compdef fapc'")
    endif()
  else()
    message(STATUS "no man page or completion installed yet (issue 18a): not checked")
  endif()
endif()

# SAME_AS_FAPC: the consumer's output (the last argument) must be byte for byte what the installed
# program writes when given the same arguments after that subcommand.
if(SAME_AS_FAPC)
  list(POP_BACK ARGS consumer_output)
  set(fapc_output ${WORK_DIR}/by-fapc-${SAME_AS_FAPC})
  get_filename_component(extension ${consumer_output} LAST_EXT)
  string(APPEND fapc_output ${extension})
  run("the installed fapc" ${prefix}/bin/fapc ${SAME_AS_FAPC} ${ARGS} -o ${fapc_output})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${consumer_output} ${fapc_output}
                  RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "${consumer_output} differs from what `fapc ${SAME_AS_FAPC}` wrote (${fapc_output})")
  endif()
endif()

# The installed tree is large (libraries with debug information): kept only when a step failed.
file(REMOVE_RECURSE ${prefix})
