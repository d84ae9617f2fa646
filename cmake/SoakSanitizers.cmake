# AddressSanitizer + UndefinedBehaviorSanitizer (preset "sanitize") and the
# libFuzzer targets (they need clang: the same preset builds them).
option(SOAK_SANITIZE "Build everything with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(SOAK_FUZZ "Build the libFuzzer targets for the scene and OBJ loaders (clang only)" OFF)

if(SOAK_SANITIZE)
  if(SOAK_WITH_CUDA)
    message(FATAL_ERROR "SOAK_SANITIZE: configure with SOAK_CUDA=OFF (the sanitizers cover the CPU backend)")
  endif()
  add_compile_options($<$<COMPILE_LANGUAGE:C,CXX>:-fsanitize=address,undefined>
                      $<$<COMPILE_LANGUAGE:C,CXX>:-fno-sanitize-recover=undefined>
                      $<$<COMPILE_LANGUAGE:C,CXX>:-fno-omit-frame-pointer>)
  add_link_options(-fsanitize=address,undefined)
endif()

if(SOAK_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SOAK_FUZZ needs clang (libFuzzer): configure with CMAKE_CXX_COMPILER=clang++")
  endif()
  # Coverage for the fuzzers' guidance in every library they call.
  add_compile_options($<$<COMPILE_LANGUAGE:C,CXX>:-fsanitize=fuzzer-no-link>)
endif()

# Sources that instantiate OpenVDB's trees: TBB's concurrent_hash_map (the
# trees' accessor registry) casts a marker value (address 3) to a node
# pointer, which UBSan's alignment check stops at. That header code is
# TBB's, not ours: these files are built without the alignment check, with
# every other check on. They are also built without optimisation and with
# line tables only: instrumenting OpenVDB's templates at -O2 -g took 228 s
# for VdbFiles.cpp alone, at -O0 -gline-tables-only 44 s, and the tests
# that write VDB files spend their time in the simulation, not in OpenVDB.
# Call from the directory that adds the sources.
function(soak_sources_using_openvdb)
  if(SOAK_SANITIZE)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS
                                "-fno-sanitize=alignment;-O0;-gline-tables-only")
  endif()
endfunction()
