# SOAK_CUDA=AUTO|ON|OFF decides whether the CUDA backend is compiled.
#   AUTO (default): built when a CUDA compiler is found, otherwise a CPU-only build.
#   ON: the CUDA toolkit is required.   OFF: CPU-only build.
# Architectures: CMAKE_CUDA_ARCHITECTURES, default "90" (Hopper: H100/H200).
# Other documented values: "80" (A100), "86;89" (Ampere/Ada consumer cards),
# or a list such as "80;90" (each added architecture adds compile time).
set(SOAK_CUDA "AUTO" CACHE STRING "Build the CUDA backend: AUTO, ON or OFF")
set_property(CACHE SOAK_CUDA PROPERTY STRINGS AUTO ON OFF)

set(SOAK_WITH_CUDA OFF)
if(NOT SOAK_CUDA STREQUAL "OFF")
  if(NOT DEFINED CMAKE_CUDA_COMPILER AND EXISTS /usr/local/cuda/bin/nvcc)
    set(CMAKE_CUDA_COMPILER /usr/local/cuda/bin/nvcc)
  endif()
  include(CheckLanguage)
  check_language(CUDA)
  if(CMAKE_CUDA_COMPILER)
    if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
      set(CMAKE_CUDA_ARCHITECTURES 90)
    endif()
    enable_language(CUDA)
    set(CMAKE_CUDA_STANDARD 17)
    set(CMAKE_CUDA_STANDARD_REQUIRED ON)
    set(CMAKE_CUDA_RUNTIME_LIBRARY Shared)
    find_package(CUDAToolkit REQUIRED)
    set(SOAK_WITH_CUDA ON)
  elseif(SOAK_CUDA STREQUAL "ON")
    message(FATAL_ERROR "SOAK_CUDA=ON but no CUDA compiler was found (set CMAKE_CUDA_COMPILER or install the CUDA toolkit)")
  endif()
endif()

if(SOAK_WITH_CUDA)
  message(STATUS "Soak: CUDA backend ON (architectures: ${CMAKE_CUDA_ARCHITECTURES}, nvcc ${CMAKE_CUDA_COMPILER_VERSION})")
else()
  message(STATUS "Soak: CPU-ONLY build (no CUDA backend; --device cuda will be refused)")
endif()

# soak_physics_sources, soak_target_options and soak_add_plugin, shared with
# the installed CMake package (SoakConfig.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/SoakPluginFunctions.cmake)
