# Installation: headers, libraries, the CLI, a CMake package
# (find_package(bccmis) -> bccmis::bccmis, bccmis::core, bccmis::invariants)
# and a pkg-config file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

add_library(bccmis_all INTERFACE)
target_link_libraries(bccmis_all INTERFACE bccmis_core bccmis_invariants)
set_target_properties(bccmis_all PROPERTIES EXPORT_NAME bccmis)
add_library(bccmis::bccmis ALIAS bccmis_all)

set_target_properties(bccmis_core PROPERTIES EXPORT_NAME core)
set_target_properties(bccmis_invariants PROPERTIES EXPORT_NAME invariants)
set_target_properties(bccmis_warnings PROPERTIES EXPORT_NAME warnings)

install(TARGETS bccmis_core bccmis_invariants bccmis_all bccmis_warnings
        EXPORT bccmisTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS bccmis RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The core's headers and the checker's (bccmis/invariants/); the other modules
# are not installed.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/bccmis/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/bccmis
        FILES_MATCHING PATTERN "*.h"
        PATTERN "fast" EXCLUDE PATTERN "oracle" EXCLUDE PATTERN "explore" EXCLUDE
        PATTERN "apps" EXCLUDE PATTERN "p4est" EXCLUDE PATTERN "cgal" EXCLUDE)
install(EXPORT bccmisTargets NAMESPACE bccmis:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/bccmis)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/bccmisConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/bccmisConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/bccmis)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/bccmisConfigVersion.cmake COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/bccmisConfig.cmake ${PROJECT_BINARY_DIR}/bccmisConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/bccmis)
configure_file(${PROJECT_SOURCE_DIR}/cmake/bccmis.pc.in ${PROJECT_BINARY_DIR}/bccmis.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/bccmis.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
