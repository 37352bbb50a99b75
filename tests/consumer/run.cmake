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
