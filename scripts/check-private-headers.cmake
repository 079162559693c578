# Fails when a header that is private to its target is included from outside its own folder
# (tests aside, which may test internals), or from one of its folder's public headers, through
# which it would leak. Run by CTest as `private_headers`:
#   cmake -DROOT=<source dir> -DHEADERS=<private headers, relative to ROOT> -P this file
cmake_minimum_required(VERSION 3.25)
if(NOT ROOT OR NOT HEADERS)
  message(FATAL_ERROR "usage: cmake -DROOT=... -DHEADERS=a.h;b.h -P check-private-headers.cmake")
endif()
file(GLOB_RECURSE sources RELATIVE ${ROOT} ${ROOT}/app/*.h ${ROOT}/app/*.cpp ${ROOT}/sim/*.h
     ${ROOT}/sim/*.cpp ${ROOT}/ui/*.h ${ROOT}/ui/*.cpp)
set(problems "")
foreach(source IN LISTS sources)
  get_filename_component(source_folder ${source} DIRECTORY)
  file(STRINGS ${ROOT}/${source} includes REGEX "^#include \"")
  foreach(header IN LISTS HEADERS)
    if(NOT "#include \"${header}\"" IN_LIST includes)
      continue()
    endif()
    get_filename_component(header_folder ${header} DIRECTORY)
    if(NOT source_folder STREQUAL header_folder)
      string(APPEND problems "  ${source} includes ${header}, private to ${header_folder}/\n")
    elseif(source MATCHES "\\.h$" AND NOT source IN_LIST HEADERS)
      string(APPEND problems "  public ${source} includes private ${header}\n")
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "Private headers used where they are not private:\n${problems}"
                      "Make the header public (carom_private_headers in its CMakeLists.txt) or "
                      "include a public one.")
endif()
list(LENGTH HEADERS count)
message(STATUS "${count} private headers stay in their folders")
