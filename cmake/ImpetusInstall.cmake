# `cmake --install` puts headers, the library and impetusConfig.cmake under the prefix, so that
# another project can `find_package(impetus REQUIRED)` and link `impetus::impetus`.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS impetus EXPORT impetusTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/impetus DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(IMPETUS_BUILD_APPS)
  install(TARGETS impetus-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(IMPETUS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/impetus)
install(EXPORT impetusTargets NAMESPACE impetus:: DESTINATION ${IMPETUS_CMAKE_DIR})
configure_package_config_file(cmake/impetusConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/impetusConfig.cmake INSTALL_DESTINATION ${IMPETUS_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/impetusConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/impetusConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/impetusConfigVersion.cmake DESTINATION ${IMPETUS_CMAKE_DIR})
