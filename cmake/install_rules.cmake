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

# A ROS 2 workspace finds a package by an empty marker file named after it in the ament index
# (ament_index_python: <prefix>/share/ament_index/resource_index/packages/<name>, searched in
# each prefix of AMENT_PREFIX_PATH) and reads share/<name>/package.xml. colcon's cmake build
# type adds neither, and no AMENT_PREFIX_PATH hook: the hook below, named in colcon.pkg, adds
# the prefix (docs/colcon.md has the sources).
file(WRITE "${PROJECT_BINARY_DIR}/ament_index/rigdesign" "")
install(FILES "${PROJECT_BINARY_DIR}/ament_index/rigdesign"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/ament_index/resource_index/packages)
install(FILES "${PROJECT_SOURCE_DIR}/package.xml" DESTINATION ${CMAKE_INSTALL_DATADIR}/rigdesign)
install(FILES "${PROJECT_SOURCE_DIR}/cmake/colcon/ament_prefix_path.dsv"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rigdesign/hook)
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
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "rigdesign developers <rigdesign@developers.invalid>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_STRIP_FILES ON)
include(CPack)
