# cmake --install puts the program, the libraries, their headers and a package config in place,
# so another project can find_package(fapc) and link fapc::codec.
include(CMakePackageConfigHelpers)
install(EXPORT fapcTargets NAMESPACE fapc:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/fapc)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/fapcConfig.cmake.in
  ${CMAKE_BINARY_DIR}/fapcConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/fapc)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/fapcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/fapcConfig.cmake ${CMAKE_BINARY_DIR}/fapcConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/fapc)
