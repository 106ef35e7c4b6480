# Sdk.cmake -- what `cmake --install` puts in the prefix for module authors (docs/modules.md): the public
# headers of dynamics, render and scenes, the shared libraries, and a CMake package so that
# `find_package(rollviz)` gives the targets rollviz::dynamics, rollviz::render, rollviz::scenes and the function
# rollviz_add_module(NAME SOURCES...).
include(CMakePackageConfigHelpers)
foreach(dir dynamics render scenes)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${ROLLVIZ_INSTALL_INCLUDEDIR}/${dir}
          FILES_MATCHING PATTERN "*.h" PATTERN "*.inl")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/include/rollviz/Version.h DESTINATION ${ROLLVIZ_INSTALL_INCLUDEDIR}/rollviz)
install(EXPORT rollvizTargets NAMESPACE rollviz:: DESTINATION ${ROLLVIZ_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rollvizConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/rollvizConfig.cmake INSTALL_DESTINATION ${ROLLVIZ_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/rollvizConfigVersion.cmake
  COMPATIBILITY ExactVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake/rollvizConfig.cmake ${PROJECT_BINARY_DIR}/cmake/rollvizConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/RollvizModule.cmake
        DESTINATION ${ROLLVIZ_INSTALL_CMAKEDIR})
