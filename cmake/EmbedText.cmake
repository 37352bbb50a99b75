# Shared by the scripts that compile files of the tree into the program (EmbedSchemas.cmake,
# transcoder/vocabulary/EmbedTables.cmake): one place that quotes a file as a C++ raw string and
# writes a generated file only when it changes.

# Appends to OUT_VAR one line `{"NAME", R"DELIM(TEXT)DELIM"},` per file of the list that follows,
# each behind INDENT; a file holding the raw string's closing delimiter is refused.
function(fapc_embed_entries out_var delim indent)
  set(body "")
  foreach(path ${ARGN})
    get_filename_component(name ${path} NAME)
    file(READ ${path} text)
    string(FIND "${text}" ")${delim}\"" clash)
    if(NOT clash EQUAL -1)
      message(FATAL_ERROR "${path} contains the raw-string delimiter )${delim}\"")
    endif()
    string(APPEND body "${indent}{\"${name}\", R\"${delim}(${text})${delim}\"},\n")
  endforeach()
  set(${out_var} "${body}" PARENT_SCOPE)
endfunction()

# Writes TEXT to OUT, touching OUT only when it changes, so an unchanged input rebuilds nothing.
function(fapc_write_if_different out text)
  file(WRITE ${out}.tmp "${text}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${out}.tmp ${out})
  file(REMOVE ${out}.tmp)
endfunction()

# At configure time: adds to TARGET the C++ file OUT, written by the script SCRIPT (run as
# cmake -DOUT=OUT -DVAR=FILES -P SCRIPT) from the files that follow, and rewritten when one of them
# or a script changes. VERBATIM keeps the ';' of a list of several files away from the shell.
function(fapc_embed_files target out script var comment)
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} "-D${var}=${ARGN}" -P ${script}
    DEPENDS ${ARGN} ${script} ${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake
    COMMENT "${comment}"
    VERBATIM)
  target_sources(${target} PRIVATE ${out})
endfunction()
