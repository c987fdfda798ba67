# Finds SuiteSparse 5.x as Debian 12 ships it: headers in /usr/include/suitesparse, no CMake
# config and no pkg-config file. Components: CHOLMOD, UMFPACK (AMD, COLAMD, CAMD, CCOLAMD and
# suitesparseconfig are pulled in as needed). Defines SuiteSparse::<Component> targets.
find_path(SuiteSparse_INCLUDE_DIR NAMES cholmod.h PATH_SUFFIXES suitesparse)
find_library(SuiteSparse_CONFIG_LIBRARY NAMES suitesparseconfig)
find_package(BLAS REQUIRED)
find_package(LAPACK REQUIRED)

set(_ss_deps_CHOLMOD amd colamd camd ccolamd)
set(_ss_deps_UMFPACK amd)
set(SuiteSparse_LIBRARIES "")
foreach(component IN LISTS SuiteSparse_FIND_COMPONENTS)
  string(TOLOWER ${component} lib)
  find_library(SuiteSparse_${component}_LIBRARY NAMES ${lib})
  if(SuiteSparse_${component}_LIBRARY)
    set(SuiteSparse_${component}_FOUND TRUE)
    if(NOT TARGET SuiteSparse::${component})
      add_library(SuiteSparse::${component} UNKNOWN IMPORTED)
      set(deps "")
      foreach(dep IN LISTS _ss_deps_${component})
        find_library(SuiteSparse_${dep}_LIBRARY NAMES ${dep})
        list(APPEND deps ${SuiteSparse_${dep}_LIBRARY})
      endforeach()
      set_target_properties(SuiteSparse::${component} PROPERTIES
        IMPORTED_LOCATION ${SuiteSparse_${component}_LIBRARY}
        INTERFACE_INCLUDE_DIRECTORIES ${SuiteSparse_INCLUDE_DIR}
        INTERFACE_LINK_LIBRARIES
          "${deps};${SuiteSparse_CONFIG_LIBRARY};${LAPACK_LIBRARIES};${BLAS_LIBRARIES}")
    endif()
    list(APPEND SuiteSparse_LIBRARIES ${SuiteSparse_${component}_LIBRARY})
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse
  REQUIRED_VARS SuiteSparse_INCLUDE_DIR SuiteSparse_CONFIG_LIBRARY
  HANDLE_COMPONENTS)
mark_as_advanced(SuiteSparse_INCLUDE_DIR SuiteSparse_CONFIG_LIBRARY)
