# One precompiled header shared by many targets (GCC only): cloudshape_precompiled_header makes
# the target it is built in, cloudshape_reuse_precompiled_header lets another target use it.

# The owner compiles nothing of its own (SOURCE is empty); LIBS give it the users' include paths.
function(cloudshape_precompiled_header owner source)
  cmake_parse_arguments(ARG "" "" "LIBS;HEADERS" ${ARGN})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_library(${owner} OBJECT ${source})
    target_link_libraries(${owner} PRIVATE ${ARG_LIBS})
    target_precompile_headers(${owner} PRIVATE ${ARG_HEADERS})
  endif()
endfunction()

# GCC uses the header in a source that defines macros the header does not mention (a program's
# data directory, say); -Winvalid-pch warns where it cannot.
function(cloudshape_reuse_precompiled_header target owner)
  if(TARGET ${owner})
    target_precompile_headers(${target} REUSE_FROM ${owner})
    target_compile_options(${target} PRIVATE -Winvalid-pch)
  endif()
endfunction()
