# `cmake --install` puts headers, the libraries (a static library per layer, and the umbrella
# impetus::impetus that links them all) and impetusConfig.cmake under the prefix, so that
# another project can `find_package(impetus REQUIRED)` and link `impetus::impetus`, and, where
# they were built, the optional impetus::geo and impetus::audio (components "geo" and "audio").
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(layer_targets GLOBAL PROPERTY IMPETUS_LAYER_TARGETS)
install(TARGETS impetus ${layer_targets} EXPORT impetusTargets
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

# The optional targets each in an export set of their own, so that the config file loads one
# only when its dependencies are found on the consumer's machine (a consumer of the core alone
# needs neither GeographicLib nor OpenAL). impetusConfig.cmake learns which were built from
# IMPETUS_BUILT_GEO / IMPETUS_BUILT_AUDIO.
set(IMPETUS_BUILT_GEO OFF)
set(IMPETUS_BUILT_AUDIO OFF)
foreach(component geo audio)
  if(TARGET impetus_${component})
    string(TOUPPER ${component} upper)
    set(IMPETUS_BUILT_${upper} ON)
    install(TARGETS impetus_${component} EXPORT impetus_${component}Targets
      ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
      LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
      INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    install(EXPORT impetus_${component}Targets NAMESPACE impetus:: DESTINATION ${IMPETUS_CMAKE_DIR})
  endif()
endforeach()

configure_package_config_file(cmake/impetusConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/impetusConfig.cmake INSTALL_DESTINATION ${IMPETUS_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/impetusConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/impetusConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/impetusConfigVersion.cmake DESTINATION ${IMPETUS_CMAKE_DIR})
