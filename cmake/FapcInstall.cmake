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

if(BUILD_SHARED_LIBS)
  set(fapc_library_kind shared)
else()
  set(fapc_library_kind static)
endif()

# pkg-config: one file per component, fapc-<component>.pc (pkg-config --libs fapc-codec). Other
# components and packages a library's headers need are Requires; those only its code needs are
# Requires.private (a static link pulls them in with pkg-config --static). The modules of packages
# found by find_package, by their imported target's prefix:
set(fapc_pkgconfig_module_ZLIB zlib)
set(fapc_pkgconfig_module_LibXml2 libxml-2.0)
set(fapc_pkgconfig_module_XercesC xerces-c)
set(fapc_pkgconfig_module_nlohmann_json nlohmann_json)
function(fapc_write_pkgconfig component target)
  get_target_property(type ${target} TYPE)
  get_target_property(public_items ${target} INTERFACE_LINK_LIBRARIES)
  if(type STREQUAL "INTERFACE_LIBRARY")
    set(all_items ${public_items})
  else()
    get_target_property(all_items ${target} LINK_LIBRARIES)
  endif()
  set(requires "")
  set(requires_private "")
  set(libs_private "")
  set(libs_public "")
  foreach(item IN LISTS all_items)
    set(public FALSE)
    if(item IN_LIST public_items)
      set(public TRUE)
    endif()
    fapc_link_item_kind("${item}" kind)
    set(module "")
    if(kind MATCHES "^component:(.*)")
      set(module fapc-${CMAKE_MATCH_1})
    elseif(kind STREQUAL "package:Threads")
      if(public)
        list(APPEND libs_public -pthread)
      else()
        list(APPEND libs_private -pthread)
      endif()
    elseif(kind MATCHES "^package:(.*)")
      set(package ${CMAKE_MATCH_1})
      if(DEFINED fapc_pkgconfig_module_${package})
        set(module ${fapc_pkgconfig_module_${package}})
      endif()
    endif()
    if(module AND public)
      list(APPEND requires ${module})
    elseif(module)
      list(APPEND requires_private ${module})
    endif()
  endforeach()
  get_target_property(extra ${target} FAPC_PKGCONFIG_PRIVATE)
  if(extra)
    list(APPEND requires_private ${extra})
  endif()
  list(REMOVE_DUPLICATES requires)
  list(REMOVE_DUPLICATES requires_private)
  list(REMOVE_ITEM requires_private ${requires} "")
  string(REPLACE ";" ", " requires "${requires}")
  string(REPLACE ";" ", " requires_private "${requires_private}")
  list(REMOVE_DUPLICATES libs_private)
  string(REPLACE ";" " " libs_private "${libs_private}")
  set(libs "")
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    set(libs "-L\${libdir} -l${target}")
  endif()
  if(libs_public)
    list(REMOVE_DUPLICATES libs_public)
    string(APPEND libs " ${libs_public}")
  endif()
  # Relocatable: the prefix is found from where the .pc file is (cmake --install --prefix anywhere).
  file(RELATIVE_PATH up /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
  string(REGEX REPLACE "/$" "" up "${up}")
  file(WRITE ${CMAKE_BINARY_DIR}/pkgconfig/fapc-${component}.pc
"prefix=\${pcfiledir}/${up}
libdir=\${prefix}/${CMAKE_INSTALL_LIBDIR}
includedir=\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}

Name: fapc-${component}
Description: fapc ${component} library (MPEG-4 face animation; docs/architecture.md)
Version: ${PROJECT_VERSION}
URL: https://github.com/fapc/fapc
Requires: ${requires}
Requires.private: ${requires_private}
Cflags: -I\${includedir} -std=c++20
Libs: ${libs}
Libs.private: ${libs_private}
")
  install(FILES ${CMAKE_BINARY_DIR}/pkgconfig/fapc-${component}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
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
  # The kind is in the file's name, so a shared and a static build installed into one prefix keep
  # both (docs/building.md, "Shared and static"); fapcConfig.cmake picks one.
  install(EXPORT fapc-${component}Targets NAMESPACE fapc:: DESTINATION ${fapc_cmake_dir}
    FILE fapc-${component}Targets-${fapc_library_kind}.cmake)
  fapc_write_pkgconfig(${component} ${target})
endforeach()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/fapcConfig.cmake.in
  ${CMAKE_BINARY_DIR}/fapcConfig.cmake INSTALL_DESTINATION ${fapc_cmake_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/fapcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/fapcConfig.cmake ${CMAKE_BINARY_DIR}/fapcConfigVersion.cmake
  DESTINATION ${fapc_cmake_dir})

# The documentation and the licence, where Debian puts them (share/doc/fapc).
# (Paths relative to the top folder, which includes this file.)
install(FILES README.md LICENSE COPYING.LGPL-2.1 COPYING.GPL-3 DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
