# `cpack -G DEB` in the build folder: fapc_<version>-1_<arch>.deb, the program for the nodes of a
# cluster (docs/cluster.md, "A package for the nodes"): the program, its man page and shell
# completions, and the files Debian asks of every package (copyright, changelog), in a component
# of its own so that the libraries, headers and CMake files of the developers' install stay out.
# Dependencies come from dpkg-shlibdeps, in Debian 12's package names. Checked by
# tests/cluster/package_test.sh (lintian, an install into a throw-away root).
set(fapc_deb_files ${CMAKE_BINARY_DIR}/deb)
set(fapc_share_dir ${CMAKE_BINARY_DIR}/tools/share)
# Debian compresses manual pages and changelogs with gzip -9n (no name, no time: reproducible).
add_custom_command(
  OUTPUT ${fapc_deb_files}/fapc.1.gz ${fapc_deb_files}/changelog.Debian.gz
  COMMAND ${CMAKE_COMMAND} -E make_directory ${fapc_deb_files}
  COMMAND ${CMAKE_COMMAND} -E copy ${fapc_share_dir}/fapc.1 ${PROJECT_SOURCE_DIR}/cmake/deb/changelog.Debian
          ${fapc_deb_files}
  COMMAND gzip -9nf ${fapc_deb_files}/fapc.1 ${fapc_deb_files}/changelog.Debian
  DEPENDS ${fapc_share_dir}/fapc.1 ${PROJECT_SOURCE_DIR}/cmake/deb/changelog.Debian
  COMMENT "Compressing the package's manual page and changelog" VERBATIM)
add_custom_target(fapc_deb_files ALL DEPENDS ${fapc_deb_files}/fapc.1.gz ${fapc_deb_files}/changelog.Debian.gz)
add_dependencies(fapc_deb_files fapc_share_files)  # the manual page is made in tools/

install(TARGETS fapc RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES ${fapc_deb_files}/fapc.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES ${fapc_share_dir}/fapc.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME fapc COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES ${fapc_share_dir}/_fapc DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions COMPONENT deb
        EXCLUDE_FROM_ALL)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/deb/copyright ${fapc_deb_files}/changelog.Debian.gz
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/fapc COMPONENT deb EXCLUDE_FROM_ALL)

set(CPACK_PACKAGE_NAME fapc)
set(CPACK_PACKAGE_VENDOR "the fapc authors")
set(CPACK_PACKAGE_CONTACT "fapc authors <fapc@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "MPEG-4 face animation transcoder")
# (Lines under 80 characters, none starting with a full stop: Debian's rules for a description.)
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "fapc turns authored facial animation (Mimic, FML and XMT-Omega scripts,\n"
    "FAP text files) into MPEG-4 face animation (FBA streams, MP4) and back,\n"
    "renders it as a face, and converts whole data sets in parallel, also\n"
    "as a sharded, resumable batch on a cluster (Slurm, Kubernetes).")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_COMPONENTS_ALL deb)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ALL_COMPONENTS_IN_ONE)
set(CPACK_DEBIAN_PACKAGE_NAME fapc)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.org/fapc")
set(CPACK_STRIP_FILES ON)
# eSpeak NG reads its voices from espeak-ng-data at run time: no library names it.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "espeak-ng-data")
include(CPack)
