# Install rules and the exported CMake package: find_package(arnoldweb) gives
# the target arnoldweb::arnoldweb.
include(CMakePackageConfigHelpers)
install(TARGETS arnoldweb EXPORT arnoldwebTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET arnoldweb_pictures)  # the pictures' plugin, opened from beside the library
  install(TARGETS arnoldweb_pictures LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/include/arnoldweb
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/lib/include/arnoldweb/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/arnoldweb)
install(TARGETS arnoldweb-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/arnoldweb/scenes)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/arnoldweb)
install(EXPORT arnoldwebTargets NAMESPACE arnoldweb:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/arnoldwebConfig.cmake.in
  ${PROJECT_BINARY_DIR}/arnoldwebConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/arnoldwebConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/arnoldwebConfig.cmake
              ${PROJECT_BINARY_DIR}/arnoldwebConfigVersion.cmake DESTINATION ${config_dir})
