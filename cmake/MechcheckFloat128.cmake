# The ~32-digit tier (mechcheck::float128): IEEE binary128 from libquadmath where the
# toolchain has it, else the same format in portable C++ (Boost's cpp_bin_float_quad: the
# same 113-bit significand and exponent range, so the same epsilon and tolerances; one
# Kepler step costs 1.5x float128's, docs/performance.md).
#
# GCC finds quadmath.h and libquadmath itself. Clang links libquadmath from the GCC
# installation it uses, but does not search GCC's include directory, where quadmath.h
# is: it is added after the system directories (-idirafter), so that Clang's own headers
# keep precedence.
#
# mechcheck_float128(<target> [MODE AUTO|quadmath|software]) tells <target>'s users which
# one to use (compile options, definitions, libraries on its INTERFACE) and sets
# MECHCHECK_FLOAT128_KIND (quadmath or software) and MECHCHECK_FLOAT128_NOTE in the caller.
# Run by mechcheck's build and by the installed package's config, each for its compiler.
include_guard(GLOBAL)

function(_mechcheck_try_quadmath result)
  set(options ${ARGN})
  try_compile(ok SOURCE_FROM_CONTENT mechcheck_float128.cpp [[
#include <boost/multiprecision/float128.hpp>
int main() {
  boost::multiprecision::float128 x = 2;
  return sqrt(x) * sqrt(x) > 1 ? 0 : 1;
}
]]
    COMPILE_DEFINITIONS ${options}
    LINK_LIBRARIES Boost::headers quadmath
    CXX_STANDARD 20 CXX_EXTENSIONS ON)
  set(${result} ${ok} PARENT_SCOPE)
endfunction()

function(mechcheck_float128 target)
  cmake_parse_arguments(ARG "" "MODE" "" ${ARGN})
  if(NOT ARG_MODE)
    set(ARG_MODE AUTO)
  endif()
  set(kind software)
  set(note "")
  set(flags "")
  if(ARG_MODE STREQUAL "AUTO" OR ARG_MODE STREQUAL "quadmath")
    _mechcheck_try_quadmath(found)
    if(found)
      set(kind quadmath)
      set(note "libquadmath")
    else()
      # GCC's include directories (Debian: /usr/lib/gcc/<triplet>/<version>/include), the
      # newest first.
      file(GLOB candidates LIST_DIRECTORIES false /usr/lib/gcc/*/*/include/quadmath.h
           /usr/local/lib/gcc/*/*/include/quadmath.h)
      list(SORT candidates COMPARE NATURAL ORDER DESCENDING)
      foreach(header IN LISTS candidates)
        get_filename_component(dir ${header} DIRECTORY)
        _mechcheck_try_quadmath(found -idirafter ${dir})
        if(found)
          set(kind quadmath)
          set(flags "SHELL:-idirafter ${dir}")
          set(note "libquadmath, quadmath.h from ${dir}")
          break()
        endif()
      endforeach()
    endif()
    if(kind STREQUAL "software")
      if(ARG_MODE STREQUAL "quadmath")
        message(FATAL_ERROR "mechcheck: MECHCHECK_FLOAT128=quadmath, but ${CMAKE_CXX_COMPILER_ID} "
                            "${CMAKE_CXX_COMPILER_VERSION} cannot build with libquadmath")
      endif()
      set(note "no libquadmath for ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}: Boost's cpp_bin_float_quad")
    endif()
  elseif(ARG_MODE STREQUAL "software")
    set(note "Boost's cpp_bin_float_quad, as asked")
  else()
    message(FATAL_ERROR "mechcheck: MECHCHECK_FLOAT128 is AUTO, quadmath or software, not '${ARG_MODE}'")
  endif()
  if(kind STREQUAL "quadmath")
    set_property(TARGET ${target} APPEND PROPERTY INTERFACE_LINK_LIBRARIES quadmath)
    if(flags)
      set_property(TARGET ${target} APPEND PROPERTY INTERFACE_COMPILE_OPTIONS ${flags})
    endif()
  else()
    set_property(TARGET ${target} APPEND PROPERTY INTERFACE_COMPILE_DEFINITIONS
                 MECHCHECK_FLOAT128_SOFTWARE)
  endif()
  set(MECHCHECK_FLOAT128_KIND ${kind} PARENT_SCOPE)
  set(MECHCHECK_FLOAT128_NOTE ${note} PARENT_SCOPE)
endfunction()
