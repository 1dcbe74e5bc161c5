# Installs the headers and an importable CMake package, so that
#   find_package(expmap) ; target_link_libraries(app PRIVATE expmap::expmap)
# works from another project.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(DIRECTORY include/expmap DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS expmap EXPORT expmapTargets)
install(EXPORT expmapTargets NAMESPACE expmap::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/expmap)

configure_package_config_file(cmake/expmapConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/expmapConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/expmap)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/expmapConfigVersion.cmake
  COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES
  ${CMAKE_CURRENT_BINARY_DIR}/expmapConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/expmapConfigVersion.cmake
  cmake/expmapDependencies.cmake cmake/FindCHOLMOD.cmake cmake/FindMETIS.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/expmap)
if(EXPMAP_BUILD_TOOLS)
  install(TARGETS expmap_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
