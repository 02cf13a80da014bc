# Installation and the CMake package (cmake --install build --prefix P; then
# find_package(sightline CONFIG) with CMAKE_PREFIX_PATH=P). Relocatable: every path in the
# package is relative to the prefix. The build tree exports the same targets, so a project can
# also use -Dsightline_DIR=<build>.
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

# Research components: the static libraries and their headers, as the program uses them
# (include/sightline/<folder>/...). Each component's export set holds its libraries; the
# package config finds the third-party packages they name before including it.
set(SIGHTLINE_RESEARCH_csp sightline_csp sightline_csp_kinds sightline_csp_yaml sightline_solvers
    sightline_nqueens)
set(SIGHTLINE_RESEARCH_files sightline_csp_files sightline_toulbar2 sightline_colouring)
set(SIGHTLINE_RESEARCH_camera sightline_level sightline_camera sightline_camera_control
    sightline_camera_baselines sightline_composition sightline_editing sightline_camera_files)
set(SIGHTLINE_RESEARCH_suites sightline_runs sightline_scene_sources sightline_replay
    sightline_suite sightline_reports sightline_execution sightline_mpi_engine
    sightline_experiments recast_detour)
foreach(component csp files camera suites)
  foreach(target IN LISTS SIGHTLINE_RESEARCH_${component})
    string(REPLACE "sightline_" "" export_name ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  endforeach()
  install(TARGETS ${SIGHTLINE_RESEARCH_${component}} EXPORT sightline-${component}
          COMPONENT ${component} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endforeach()
foreach(pair csp:csp csp:solvers camera:domains suites:experiments)
  string(REPLACE ":" ";" pair ${pair})
  list(GET pair 0 component)
  list(GET pair 1 folder)
  install(DIRECTORY ${folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sightline/${folder}
          COMPONENT ${component} FILES_MATCHING PATTERN "*.h")
endforeach()
install(DIRECTORY csp/files/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sightline/csp/files
        COMPONENT files FILES_MATCHING PATTERN "*.h")
if(MPI_C_FOUND)
  set(SIGHTLINE_WITH_MPI ON)
else()
  set(SIGHTLINE_WITH_MPI OFF)
endif()

foreach(component runtime levels csp files camera suites)
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
