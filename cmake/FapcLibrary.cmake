# fapc_library(NAME COMPONENT): one shape for every library of the project.
# Sources are every .cpp under src/ (so adding a file needs no CMake edit); public headers live
# under include/fapc/<component>/ and are installed as they are. The library is fapc::<COMPONENT>
# in the build and in the installed package, where it is the component of that name
# (find_package(fapc COMPONENTS <COMPONENT>)); which other components and packages it needs is
# read from its link libraries when the package is written (cmake/FapcInstall.cmake).
# STATIC or SHARED follows BUILD_SHARED_LIBS.
function(fapc_library name component)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  if(NOT sources)
    return()  # a library whose first source has not landed yet
  endif()
  add_library(${name} ${sources})
  add_library(fapc::${component} ALIAS ${name})
  # Shared libraries are libfapc_<component>.so.0.1.0 with soname .so.0.1: before 1.0 a minor
  # version may change the ABI (the package's version file says the same: SameMinorVersion).
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${component} VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  # The public headers are C++20: a consumer's compiler is told so by the target, not by a guess.
  target_compile_features(${name} PUBLIC cxx_std_20)
  target_include_directories(${name}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${name} PRIVATE $<BUILD_INTERFACE:fapc_flags>)
  install(TARGETS ${name} EXPORT fapc-${component}Targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
  set_property(GLOBAL APPEND PROPERTY FAPC_COMPONENTS ${component})
  set_property(GLOBAL PROPERTY FAPC_COMPONENT_TARGET_${component} ${name})
endfunction()

# fapc_umbrella(NAME COMPONENT LIBRARIES...): a component with no code of its own that stands for
# several (fapc::xmt = every XML front end and the MPEG-4 layer, kept for existing users).
function(fapc_umbrella name component)
  add_library(${name} INTERFACE)
  add_library(fapc::${component} ALIAS ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${component})
  target_link_libraries(${name} INTERFACE ${ARGN})
  install(TARGETS ${name} EXPORT fapc-${component}Targets)
  set_property(GLOBAL APPEND PROPERTY FAPC_COMPONENTS ${component})
  set_property(GLOBAL PROPERTY FAPC_COMPONENT_TARGET_${component} ${name})
endfunction()
