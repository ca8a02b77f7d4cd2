# Cyclone DDS for the cross-vendor programs (tools/interop, tests/dds): optional, from Debian's
# cyclonedds-dev and cyclonedds-tools. CLOUDSHAPE_CYCLONE says whether both were found.
find_package(CycloneDDS QUIET)
find_program(IDLC_PROGRAM idlc)
if(CycloneDDS_FOUND AND IDLC_PROGRAM)
  set(CLOUDSHAPE_CYCLONE TRUE)
  enable_language(C)
else()
  set(CLOUDSHAPE_CYCLONE FALSE)
  message(STATUS "Cyclone DDS programs: skipped (needs cyclonedds-dev and cyclonedds-tools)")
endif()

# An executable from `source` whose C types idlc generates from `idl`, linked to Cyclone DDS.
function(cloudshape_cyclone_executable target source idl)
  get_filename_component(name ${idl} NAME_WE)
  set(gen ${CMAKE_CURRENT_BINARY_DIR}/${target}_idl)
  add_custom_command(
    OUTPUT ${gen}/${name}.c ${gen}/${name}.h
    COMMAND ${CMAKE_COMMAND} -E make_directory ${gen}
    COMMAND ${IDLC_PROGRAM} -o ${gen} ${idl}
    DEPENDS ${idl}
    COMMENT "idlc ${name}.idl (Cyclone DDS, C) for ${target}"
    VERBATIM)
  add_executable(${target} ${source} ${gen}/${name}.c)
  # Generated code is not ours to fix: no warnings from it.
  set_source_files_properties(${gen}/${name}.c PROPERTIES COMPILE_OPTIONS -w)
  target_include_directories(${target} PRIVATE ${gen})
  target_link_libraries(${target} PRIVATE CycloneDDS::ddsc)
endfunction()
