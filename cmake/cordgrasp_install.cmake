# Install rules: the libraries (exported as cordgrasp::core, ::collision, ::sim, ::render,
# ::jobs), their public headers, the cordgrasp command, the shipped assets (share/cordgrasp)
# and the CMake package (lib/cmake/cordgrasp: config, version, targets).
include(CMakePackageConfigHelpers)

set(CORDGRASP_LIBRARIES cordgrasp_core cordgrasp_collision cordgrasp_sim cordgrasp_render
    cordgrasp_jobs)
# Static libraries go into the Python module (a shared object) too.
set_target_properties(${CORDGRASP_LIBRARIES} PROPERTIES POSITION_INDEPENDENT_CODE ON)
foreach(lib ${CORDGRASP_LIBRARIES})
  string(REPLACE "cordgrasp_" "" name ${lib})
  set_target_properties(${lib} PROPERTIES EXPORT_NAME ${name})
endforeach()
# The warning flags target is linked PRIVATE; exported only so the export set is complete (it
# carries no usage requirement a consumer sees, except sanitizer link flags).
set_target_properties(cordgrasp_options PROPERTIES EXPORT_NAME internal_options)

install(TARGETS ${CORDGRASP_LIBRARIES} cordgrasp_options EXPORT cordgrasp-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS cordgrasp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY core/include/ sim/include/ sim/collision/include/ render/include/
                  tools/jobs/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(DIRECTORY assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/cordgrasp)

set(CORDGRASP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/cordgrasp)
install(EXPORT cordgrasp-targets NAMESPACE cordgrasp:: DESTINATION ${CORDGRASP_CMAKE_DIR})
configure_package_config_file(cmake/cordgrasp-config.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/cordgrasp-config.cmake
  INSTALL_DESTINATION ${CORDGRASP_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
# 0.x: minor versions may break the API.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/cordgrasp-config-version.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/cordgrasp-config.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/cordgrasp-config-version.cmake
              ${CMAKE_CURRENT_SOURCE_DIR}/cmake/FindGLPK.cmake
        DESTINATION ${CORDGRASP_CMAKE_DIR})

# Installs this build into a temporary prefix and builds and runs tests/install against it.
if(CORDGRASP_BUILD_TESTS)
  set(_cordgrasp_test_python "")
  if(CORDGRASP_PYTHON_MODULE)
    set(_cordgrasp_test_python ${Python_EXECUTABLE})
  endif()
  add_test(NAME Install.ConsumerPlansMug
           COMMAND ${CMAKE_SOURCE_DIR}/tests/install/run_install_test.sh ${CMAKE_BINARY_DIR}
                   ${_cordgrasp_test_python})
  set_tests_properties(Install.ConsumerPlansMug PROPERTIES LABELS install TIMEOUT 300
                       PASS_REGULAR_EXPRESSION "install test: ok")
endif()
