# The order in which a program loads deal.II's ~200 shared libraries, chosen
# so that the dynamic loader's symbol lookups at start-up are short.
#
# At start-up the loader binds every symbolic relocation of every library
# (vtables, typeinfo, addresses of functions and data) by searching the
# libraries in load order until one defines the symbol. In the order the
# linker gives (the executable's own few libraries, then breadth first), a
# library such as OpenBLAS, gmsh or OpenCASCADE finds its own symbols only
# after a hundred others, and start-up costs more than a small plate takes
# to solve. Most of a library's symbolic relocations resolve to itself, so
# loading the libraries in decreasing order of their counts shortens the
# searches (figures: benchmarks/plate_multigrid/README.md, "Why 90 x 90
# cannot reach 0.3 s").
#
# unilateral_lookup_order(<variable>) sets <variable> to link items that
# name deal.II's libraries in that order, kept by --no-as-needed (the linker
# would otherwise drop those the executable does not call directly). The
# counts come from each library's dynamic section (DT_RELASZ minus
# DT_RELACOUNT: its non-relative relocations, without the lazily bound PLT
# slots). A symbol that several libraries define (BLAS's, LAPACK's) binds
# to the first in this order. Where ldd or readelf is missing, or deal.II is
# not a shared library, <variable> is empty and the linker's order stays:
# the same program, started more slowly.
function(unilateral_lookup_order variable)
  set(${variable} "" PARENT_SCOPE)
  # The deal.II library this build links (deal_ii_setup_target's choice):
  # naming the other one would load both.
  string(TOUPPER "${CMAKE_BUILD_TYPE}" _build_type)
  if(_build_type STREQUAL "DEBUG")
    list(GET DEAL_II_LIBRARIES_DEBUG 0 _dealii)
  else()
    list(GET DEAL_II_LIBRARIES_RELEASE 0 _dealii)
  endif()
  find_program(UNILATERAL_LDD ldd)
  find_program(UNILATERAL_READELF NAMES readelf ${CMAKE_READELF})
  if(NOT UNILATERAL_LDD OR NOT UNILATERAL_READELF OR
     NOT _dealii MATCHES "\\.so")
    message(STATUS "Library load order: left to the linker (no ldd/readelf "
      "or no shared deal.II)")
    return()
  endif()
  execute_process(COMMAND ${UNILATERAL_LDD} ${_dealii}
    OUTPUT_VARIABLE _ldd RESULT_VARIABLE _ldd_result ERROR_QUIET)
  if(NOT _ldd_result EQUAL 0)
    message(STATUS "Library load order: left to the linker (ldd failed)")
    return()
  endif()
  get_filename_component(_dealii_real ${_dealii} REALPATH)
  set(_libraries ${_dealii_real})
  string(REGEX MATCHALL "=> (/[^ \n]+)" _found "${_ldd}")
  foreach(_match ${_found})
    string(SUBSTRING "${_match}" 3 -1 _library)
    list(APPEND _libraries ${_library})
  endforeach()
  execute_process(COMMAND ${UNILATERAL_READELF} --dynamic --wide ${_libraries}
    OUTPUT_VARIABLE _dynamic ERROR_QUIET)
  # One "File: <path>" block per library; sort keys "<count>|<path>".
  string(REPLACE "\nFile: " "\n@File: " _dynamic "\n${_dynamic}")
  string(REPLACE ";" "," _dynamic "${_dynamic}")
  string(REPLACE "\n@" ";" _blocks "${_dynamic}")
  set(_keyed "")
  foreach(_block ${_blocks})
    if(NOT _block MATCHES "^File: ([^\n]+)")
      continue()
    endif()
    set(_library "${CMAKE_MATCH_1}")
    set(_bytes 0)
    set(_relative 0)
    if(_block MATCHES "\\(RELASZ\\) +([0-9]+)")
      set(_bytes ${CMAKE_MATCH_1})
    endif()
    if(_block MATCHES "\\(RELACOUNT\\) +([0-9]+)")
      set(_relative ${CMAKE_MATCH_1})
    endif()
    math(EXPR _symbolic "${_bytes} / 24 - ${_relative}") # 24 bytes per Rela
    string(LENGTH "${_symbolic}" _digits)
    math(EXPR _pad "12 - ${_digits}")
    string(REPEAT "0" ${_pad} _zeros)
    list(APPEND _keyed "${_zeros}${_symbolic}|${_library}")
  endforeach()
  list(LENGTH _keyed _count)
  if(_count LESS 2)
    message(STATUS "Library load order: left to the linker (readelf gave "
      "no dynamic sections)")
    return()
  endif()
  list(SORT _keyed ORDER DESCENDING)
  set(_items "-Wl,--no-as-needed")
  foreach(_entry ${_keyed})
    string(REGEX REPLACE "^[0-9]+\\|" "" _library "${_entry}")
    list(APPEND _items "${_library}")
  endforeach()
  list(APPEND _items "-Wl,--as-needed")
  message(STATUS "Library load order: ${_count} libraries by their "
    "symbolic relocations")
  set(${variable} "${_items}" PARENT_SCOPE)
endfunction()
