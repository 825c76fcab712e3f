# Copies every shared library LIBRARY needs, beyond glibc, into DEST (named by soname) and
# points their RUNPATH at $ORIGIN, so that the FMU loads on a machine without them.
# Usage: cmake -DLIBRARY=... -DDEST=... -P bundle_runtime_libraries.cmake
file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES ${LIBRARY}
  RESOLVED_DEPENDENCIES_VAR resolved
  UNRESOLVED_DEPENDENCIES_VAR unresolved
  PRE_EXCLUDE_REGEXES "^ld-linux" "^libc\\.so" "^libm\\.so" "^libpthread\\.so" "^libdl\\.so"
                      "^librt\\.so" "^libresolv\\.so")
if(unresolved)
  message(FATAL_ERROR "unresolved runtime dependencies: ${unresolved}")
endif()
find_program(PATCHELF patchelf REQUIRED)
foreach(dependency IN LISTS resolved)
  get_filename_component(soname ${dependency} NAME)
  execute_process(COMMAND cp -L ${dependency} ${DEST}/${soname} COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND ${PATCHELF} --set-rpath $ORIGIN ${DEST}/${soname} COMMAND_ERROR_IS_FATAL ANY)
  message(STATUS "bundled ${soname}")
endforeach()
