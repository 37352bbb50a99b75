# cmake --install puts the program, the libraries, their headers and a package config in place, so
# another project can find_package(fapc COMPONENTS codec) and link fapc::codec. Each component
# (one per library, see fapc_library) has its own target file, fapc-<component>Targets.cmake, and
# the config file loads only the requested components, the components they need and the packages
# those link: a codec user needs ZLIB, not libxml2 or Xerces-C (docs/building.md).
include(CMakePackageConfigHelpers)
set(fapc_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/fapc)

# What one link item of a library is in the package: a component of ours ("component:NAME"), a
# package found by find_package ("package:NAME", the part before "::" of an imported target), or
# nothing (build-only items such as the warning flags).
function(fapc_link_item_kind item out)
  set(kind "")
  if(item MATCHES "^\\$<LINK_ONLY:(.*)>$")
    set(item ${CMAKE_MATCH_1})
  endif()
  if(item MATCHES "^\\$<")
    # $<BUILD_INTERFACE:...> and other build-tree-only expressions.
  elseif(TARGET ${item})
    get_target_property(aliased ${item} ALIASED_TARGET)
    if(aliased)
      set(item ${aliased})
    endif()
    get_property(component GLOBAL PROPERTY FAPC_TARGET_COMPONENT_${item})
    if(component)
      set(kind component:${component})
    elseif(item MATCHES "^([A-Za-z0-9_]+)::")
      set(kind package:${CMAKE_MATCH_1})
    endif()
  endif()
  set(${out} ${kind} PARENT_SCOPE)
endfunction()

get_property(fapc_components GLOBAL PROPERTY FAPC_COMPONENTS)
foreach(component IN LISTS fapc_components)
  get_property(target GLOBAL PROPERTY FAPC_COMPONENT_TARGET_${component})
  set_property(GLOBAL PROPERTY FAPC_TARGET_COMPONENT_${target} ${component})
endforeach()

# The table the config file reads, in the order the components were defined (a component comes
# after those it needs, as add_subdirectory order guarantees).
set(FAPC_COMPONENT_TABLE "set(_fapc_components ${fapc_components})\n")
foreach(component IN LISTS fapc_components)
  get_property(target GLOBAL PROPERTY FAPC_COMPONENT_TARGET_${component})
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(items ${target} INTERFACE_LINK_LIBRARIES)
  else()
    get_target_property(items ${target} LINK_LIBRARIES)
  endif()
  set(requires "")
  set(packages "")
  foreach(item IN LISTS items)
    fapc_link_item_kind("${item}" kind)
    if(kind MATCHES "^component:(.*)")
      list(APPEND requires ${CMAKE_MATCH_1})
    elseif(kind MATCHES "^package:(.*)")
      list(APPEND packages ${CMAKE_MATCH_1})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES requires)
  list(REMOVE_DUPLICATES packages)
  string(APPEND FAPC_COMPONENT_TABLE
    "set(_fapc_${component}_requires ${requires})\nset(_fapc_${component}_packages ${packages})\n")
  install(EXPORT fapc-${component}Targets NAMESPACE fapc:: DESTINATION ${fapc_cmake_dir}
    FILE fapc-${component}Targets.cmake)
endforeach()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/fapcConfig.cmake.in
  ${CMAKE_BINARY_DIR}/fapcConfig.cmake INSTALL_DESTINATION ${fapc_cmake_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/fapcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/fapcConfig.cmake ${CMAKE_BINARY_DIR}/fapcConfigVersion.cmake
  DESTINATION ${fapc_cmake_dir})
