# `cmake --install` and the Debian package (CPack): the binary in bin/, the bundled data in
# share/rigdesign/ (the layout the binary looks for beside itself, so the prefix can move), the
# documentation in share/doc/rigdesign/.
include(GNUInstallDirs)

install(TARGETS rigdesign RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES "${PROJECT_SOURCE_DIR}/sensors.yaml" DESTINATION ${CMAKE_INSTALL_DATADIR}/rigdesign)
# rigs/robots holds third-party robot descriptions with their licence notices (SOURCES.md and
# the packages' own LICENSE files), which travel with them.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/rigs" "${PROJECT_SOURCE_DIR}/data"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rigdesign)
install(FILES "${PROJECT_SOURCE_DIR}/README.md" DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/" DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Debian package: `cpack -G DEB` in a Release build folder (README, "Install"). The runtime
# dependencies are read from the binary by dpkg-shlibdeps (Debian's dpkg-dev), so the package
# asks for exactly the libraries this build links, on whichever release it was built.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME rigdesign)
set(CPACK_PACKAGE_VENDOR "rigdesign developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Design and check the sensor rig of an autonomous mobile robot")
set(CPACK_PACKAGE_INSTALL_DIRECTORY rigdesign)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "rigdesign developers <rigdesign@invalid>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_STRIP_FILES ON)
include(CPack)
