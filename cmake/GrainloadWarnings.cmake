# Warnings and the shared compile settings every grainload target gets.
add_library(grainload_settings INTERFACE)
target_compile_options(grainload_settings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion
  # GCC 12 at -O3 reports -Wrestrict inside libstdc++'s operator+(const char*, std::string&&)
  # for plain "literal" + string expressions, a false positive (GCC bug 105651).
  $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
target_include_directories(grainload_settings INTERFACE ${PROJECT_SOURCE_DIR})
target_link_libraries(grainload_settings INTERFACE Eigen3::Eigen OpenMP::OpenMP_CXX)

# One library per module, its sources globbed so that adding a file needs no CMake edit.
function(grainload_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(sources)
    add_library(${name} STATIC ${sources})
    target_link_libraries(${name} PUBLIC grainload_settings ${ARG_DEPENDS})
  else()
    add_library(${name} INTERFACE)
    target_link_libraries(${name} INTERFACE grainload_settings ${ARG_DEPENDS})
  endif()
endfunction()
