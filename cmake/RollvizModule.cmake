# RollvizModule.cmake -- rollviz_add_module(NAME SOURCES...): a rollviz module (docs/modules.md) from its
# sources: a shared library lib<NAME>.so built with C++20 against the installed rollviz, whose entry point
# (ROLLVIZ_MODULE in scenes/Module.h) registers its models, tools and integrators. rollviz loads it from
# ROLLVIZ_MODULE_PATH, ~/.local/lib/rollviz/modules or `--module FILE`; `install(TARGETS NAME DESTINATION ...)`
# as usual.
function(rollviz_add_module name)
  add_library(${name} MODULE ${ARGN})
  target_compile_features(${name} PRIVATE cxx_std_20)
  set_target_properties(${name} PROPERTIES PREFIX "lib" CXX_EXTENSIONS OFF)
  target_link_libraries(${name} PRIVATE rollviz::scenes)
endfunction()

# a module is built optimised unless its project chooses a build type (Eigen at -O0 is tens of times slower)
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "rollviz module: optimised by default" FORCE)
endif()
# quiet Makefile builds: a module's build prints only what goes wrong (the compiler's messages)
set_property(GLOBAL PROPERTY RULE_MESSAGES OFF)
set_property(GLOBAL PROPERTY TARGET_MESSAGES OFF)
