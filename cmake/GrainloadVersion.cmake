# Version and git hash for io/version.hpp. The hash is read at every build, not only at
# configure time, so summary.json names the commit that was built; the header is rewritten
# only when its text changes, so an unchanged hash rebuilds nothing.
set(GRAINLOAD_VERSION_HEADER ${PROJECT_BINARY_DIR}/generated/io/version.hpp)
add_custom_target(grainload_version
  COMMAND ${CMAKE_COMMAND}
    -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
    -DOUTPUT=${GRAINLOAD_VERSION_HEADER}
    -DVERSION=${PROJECT_VERSION}
    -P ${PROJECT_SOURCE_DIR}/cmake/WriteVersion.cmake
  BYPRODUCTS ${GRAINLOAD_VERSION_HEADER}
  COMMENT "Reading the git hash")
