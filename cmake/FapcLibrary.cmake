# fapc_library(NAME ALIAS DEPS...): one shape for every library of the project.
# Sources are every .cpp under src/ (so adding a file needs no CMake edit); public headers live
# under include/fapc/<area>/ and are installed as they are.
function(fapc_library name alias)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  if(NOT sources)
    return()  # a library whose first source has not landed yet
  endif()
  add_library(${name} STATIC ${sources})
  add_library(fapc::${alias} ALIAS ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${alias})
  target_include_directories(${name}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${name} PRIVATE $<BUILD_INTERFACE:fapc_flags>)
  install(TARGETS ${name} EXPORT fapcTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
