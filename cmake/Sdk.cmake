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
# Without their debug info by default: a dev build's librollviz_dynamics.so carries ~350 MB of it, which a module
# author does not need (ROLLVIZ_INSTALL_DEBUG_INFO=ON keeps it; `cmake --install --strip` strips symbols too).
# Runs after the libraries' and executables' own rules (CMP0082: install rules in the order they are declared).
option(ROLLVIZ_INSTALL_DEBUG_INFO "keep the debug info in the libraries and executables that cmake --install puts in the prefix" OFF)
if(NOT ROLLVIZ_INSTALL_DEBUG_INFO AND CMAKE_STRIP)
  set(rv_installed_binaries)
  foreach(t rv_dynamics rv_render rv_scenes)
    list(APPEND rv_installed_binaries "${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:${t}>")
  endforeach()
  foreach(t rollviz rollviz-osmesa)
    if(TARGET ${t})
      list(APPEND rv_installed_binaries "bin/$<TARGET_FILE_NAME:${t}>")
    endif()
  endforeach()
  if(TARGET _rollviz)
    list(APPEND rv_installed_binaries "${ROLLVIZ_PYTHON_INSTALL_DIR}/rollviz/$<TARGET_FILE_NAME:_rollviz>")
  endif()
  install(CODE "
    foreach(f ${rv_installed_binaries})
      if(IS_ABSOLUTE \"\${f}\")
        set(p \"\$ENV{DESTDIR}\${f}\")
      else()
        set(p \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/\${f}\")
      endif()
      if(EXISTS \"\${p}\")
        execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug \"\${p}\" RESULT_VARIABLE rv_strip)
        if(NOT rv_strip EQUAL 0)
          message(WARNING \"rollviz: could not strip the debug info of \${p}\")
        endif()
      endif()
    endforeach()")
endif()
