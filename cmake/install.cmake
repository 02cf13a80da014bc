# Installation and the CMake package (cmake --install build --prefix P; then
# find_package(sightline CONFIG) with CMAKE_PREFIX_PATH=P). Relocatable: every path in the
# package is relative to the prefix. The build tree exports the same targets, so a project can
# also use -Dsightline_DIR=<build>.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SIGHTLINE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/sightline)

install(TARGETS sightline_runtime EXPORT sightline-runtime COMPONENT runtime
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES
  include/sightline/vec3.h include/sightline/world.h include/sightline/camera.h
  include/sightline/sightline.h ${PROJECT_BINARY_DIR}/include/sightline/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sightline COMPONENT runtime)
install(TARGETS sightline_levels EXPORT sightline-levels COMPONENT levels
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES include/sightline/level.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sightline COMPONENT levels)
install(TARGETS sightline RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)

foreach(component runtime levels)
  install(EXPORT sightline-${component} NAMESPACE sightline::
          FILE sightline-${component}-targets.cmake DESTINATION ${SIGHTLINE_CMAKE_DIR}
          COMPONENT ${component})
  export(EXPORT sightline-${component} NAMESPACE sightline::
         FILE ${PROJECT_BINARY_DIR}/sightline-${component}-targets.cmake)
endforeach()

configure_package_config_file(cmake/sightlineConfig.cmake.in
  ${PROJECT_BINARY_DIR}/sightlineConfig.cmake INSTALL_DESTINATION ${SIGHTLINE_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sightlineConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sightlineConfig.cmake
              ${PROJECT_BINARY_DIR}/sightlineConfigVersion.cmake
        DESTINATION ${SIGHTLINE_CMAKE_DIR} COMPONENT runtime)
