# GRAINLOAD_SANITIZE and GRAINLOAD_FUZZ (see the top-level CMakeLists.txt). Set before the
# modules are added, so that every library, the CLI and the tests share the instrumentation.
if(GRAINLOAD_SANITIZE OR GRAINLOAD_FUZZ)
  # Undefined behaviour aborts (no recovery), so that a test or a fuzz input that triggers it
  # fails instead of printing a line nobody reads.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
    -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
if(GRAINLOAD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "GRAINLOAD_FUZZ needs clang (libFuzzer): configure with "
      "-DCMAKE_CXX_COMPILER=clang++, as scripts/fuzz.sh does")
  endif()
  set(ignorelist ${PROJECT_SOURCE_DIR}/cmake/fuzz_coverage_ignorelist.txt)
  # The list's hash goes into the flags, so that a changed list rebuilds everything, also
  # through ccache (which hashes the command line, not the files it names).
  file(MD5 ${ignorelist} ignorelist_hash)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ignorelist})
  add_compile_options(-fsanitize=fuzzer-no-link -fsanitize-coverage-ignorelist=${ignorelist}
    -DGRAINLOAD_COVERAGE_IGNORELIST=${ignorelist_hash})
endif()
