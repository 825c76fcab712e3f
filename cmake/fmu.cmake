# The FMI 2.0 layer and the packaging of ContactBody.fmu.

# FMI headers come from the installed fmpy package (never copied into the repository).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
execute_process(
  COMMAND ${Python3_EXECUTABLE} -c "import fmpy, os; print(os.path.join(os.path.dirname(fmpy.__file__), 'c-code'))"
  OUTPUT_VARIABLE FMI_HEADERS_DIR OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE fmpy_missing)
if(fmpy_missing OR NOT EXISTS "${FMI_HEADERS_DIR}/fmi2Functions.h")
  message(FATAL_ERROR "FMI 2 headers not found: install fmpy for ${Python3_EXECUTABLE} (scripts/setup.sh does)")
endif()

set(FMU_SOURCES fmu_src/fmi2_functions.cpp fmu_src/instance.cpp fmu_src/model.cpp fmu_src/variables.cpp
  fmu_src/fmu_state.cpp)

add_library(ContactBody SHARED ${FMU_SOURCES})
target_include_directories(ContactBody PRIVATE fmu_src ${FMI_HEADERS_DIR})
target_link_libraries(ContactBody PRIVATE contactbody_solver)
set_target_properties(ContactBody PROPERTIES
  PREFIX "" CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
  BUILD_RPATH "$ORIGIN" INSTALL_RPATH "$ORIGIN")
# Self-contained: libstdc++/libgcc inside, their symbols hidden; other libraries beside it.
# (The sanitizer build links them dynamically: the sanitizer runtimes need the shared ones.)
if(NOT CONTACTBODY_SANITIZE)
  target_link_options(ContactBody PRIVATE -static-libstdc++ -static-libgcc -Wl,--exclude-libs,ALL)
endif()
target_link_options(ContactBody PRIVATE -Wl,--enable-new-dtags -Wl,--no-undefined)

add_executable(generate_model_description fmu_src/generate_model_description.cpp fmu_src/variables.cpp)
target_include_directories(generate_model_description PRIVATE fmu_src)
target_link_libraries(generate_model_description PRIVATE contactbody_solver)

set(FMU_DIR ${CMAKE_BINARY_DIR}/fmu)
set(FMU_FILE ${CMAKE_BINARY_DIR}/ContactBody.fmu)
file(GLOB SHIPPED_SOURCES CONFIGURE_DEPENDS
  ${CMAKE_SOURCE_DIR}/fmu_src/*.cpp ${CMAKE_SOURCE_DIR}/fmu_src/*.hpp
  ${CMAKE_SOURCE_DIR}/solver/*.cpp ${CMAKE_SOURCE_DIR}/solver/*.hpp)
add_custom_command(OUTPUT ${FMU_FILE}
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${FMU_DIR}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${FMU_DIR}/binaries/linux64 ${FMU_DIR}/sources
  COMMAND generate_model_description ${FMU_DIR}/modelDescription.xml
  COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_FILE:ContactBody> ${FMU_DIR}/binaries/linux64/
  COMMAND ${CMAKE_COMMAND} -DLIBRARY=$<TARGET_FILE:ContactBody> -DDEST=${FMU_DIR}/binaries/linux64
          -P ${CMAKE_SOURCE_DIR}/cmake/bundle_runtime_libraries.cmake
  COMMAND ${CMAKE_COMMAND} -E copy ${SHIPPED_SOURCES} ${FMU_DIR}/sources/
  COMMAND ${CMAKE_COMMAND} -E rm -f ${FMU_FILE}
  COMMAND ${CMAKE_COMMAND} -E chdir ${FMU_DIR}
          ${CMAKE_COMMAND} -E tar cf ${FMU_FILE} --format=zip modelDescription.xml binaries sources
  DEPENDS ContactBody generate_model_description ${SHIPPED_SOURCES}
          ${CMAKE_SOURCE_DIR}/cmake/bundle_runtime_libraries.cmake
  COMMENT "Packaging ContactBody.fmu")
add_custom_target(fmu ALL DEPENDS ${FMU_FILE})
