# Functions for building Soak code, used by Soak's own tree and, installed,
# by plugins built outside it (find_package(Soak) includes this file).
# They read SOAK_WITH_CUDA: whether Soak was built with its CUDA backend.

# soak_physics_sources(<target> <files...>): files written once for both
# backends. With CUDA they are compiled by nvcc (so forEach launches kernels),
# otherwise by the C++ compiler (forEach runs OpenMP loops).
function(soak_physics_sources target)
  target_sources(${target} PRIVATE ${ARGN})
  if(SOAK_WITH_CUDA)
    set_source_files_properties(${ARGN} TARGET_DIRECTORY ${target} PROPERTIES LANGUAGE CUDA)
  endif()
endfunction()

function(soak_target_options target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra>
    $<$<COMPILE_LANGUAGE:CUDA>:--extended-lambda --expt-relaxed-constexpr --default-stream per-thread -Xcompiler=-fopenmp -Xcompiler=-Wall --diag-suppress=20012>)
  if(SOAK_WITH_CUDA)
    target_compile_definitions(${target} PRIVATE SOAK_WITH_CUDA=1)
  endif()
endfunction()

# soak_add_plugin(<Name> SOURCES <files...> [PHYSICS <files...>]): the plugin
# library libsoak_<Name>.so, loaded at run time (plugin directory, --plugin
# PATH or <Plugin path="..."/>). SOURCES are plain C++ (registration,
# modules); PHYSICS are the files with forEach loops, compiled for the
# backend Soak was built with. The library goes to
# SOAK_PLUGIN_OUTPUT_DIRECTORY (default: <build>/soak-plugins).
function(soak_add_plugin name)
  cmake_parse_arguments(P "" "" "SOURCES;PHYSICS" ${ARGN})
  set(target soak_${name})
  add_library(${target} MODULE ${P_SOURCES})
  if(P_PHYSICS)
    soak_physics_sources(${target} ${P_PHYSICS})
  endif()
  target_link_libraries(${target} PRIVATE Soak::core)
  soak_target_options(${target})
  if(NOT SOAK_PLUGIN_OUTPUT_DIRECTORY)
    set(SOAK_PLUGIN_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/soak-plugins)
  endif()
  set_target_properties(${target} PROPERTIES
    LIBRARY_OUTPUT_DIRECTORY ${SOAK_PLUGIN_OUTPUT_DIRECTORY}
    PREFIX "lib"
    BUILD_RPATH "$ORIGIN/..;$ORIGIN/../lib"
    INSTALL_RPATH "$ORIGIN/..")
endfunction()
