# The FMU binaries: ContactBody and ContactBody3D (the FMI layers over the solver) and the companion FMUs of
# examples/system (BeltDrive, Press), each one shared library with nothing inside it that the
# platform's C library does not provide, exporting only the FMI functions.

function(make_self_contained target)
  set_target_properties(${target} PROPERTIES PREFIX "" C_VISIBILITY_PRESET hidden
                        CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  if(WIN32)
    # The C and C++ runtimes and winpthreads linked in: imports only Windows' own DLLs.
    target_link_options(${target} PRIVATE -static -s -Wl,--gc-sections)
  elseif(CONTACTBODY_ZIG AND APPLE)
    # zig links its libc++ in and signs the dylib ad hoc. Its Mach-O linker takes no list of
    # exports: hidden visibility leaves the FMI functions (default visibility by the FMI
    # headers) and the two symbols every dylib has (python_tests/test_portable.py checks them).
    target_link_options(${target} PRIVATE -s -Wl,-dead_strip)
    # Its own name without the build's path (an FMU is loaded by path, never linked against).
    set_target_properties(${target} PROPERTIES BUILD_WITH_INSTALL_NAME_DIR ON INSTALL_NAME_DIR @rpath)
  elseif(CONTACTBODY_ZIG)
    # zig links its libc++ in; glibc symbols no newer than the target's 2.17.
    target_sources(${target} PRIVATE ${PROJECT_SOURCE_DIR}/fmu_src/zig_static_destructors.cpp)
    # -u __udivti3 links zig's compiler_rt in, whose exp, log, floor, ceil and sqrt then take
    # the place of the host glibc's: the slip-rate law's exp gives the same bits on every Linux
    # (glibc's exp differs between versions, and its FMA variant between processors). Without
    # it, whether compiler_rt came in depended on what else the binary used (<sstream> did).
    target_link_options(${target} PRIVATE -s -Wl,--gc-sections -Wl,-u,__udivti3
                        -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/fmi_exports.map)
  elseif(NOT CONTACTBODY_SANITIZE)
    # The native build (not what users get): libstdc++ and libgcc inside, symbols hidden.
    # (The sanitizer build links them dynamically: the sanitizer runtimes need the shared ones.)
    target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc -Wl,--exclude-libs,ALL
                        -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/fmi_exports.map)
  endif()
  if(NOT WIN32 AND NOT APPLE)  # (Mach-O links refuse undefined symbols by default)
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
endfunction()

# One binary per model, both standards: ContactBody.fmu (FMI 2.0) and ContactBody_fmi3.fmu
# (FMI 3.0) carry the same library, which exports the fmi2 and the fmi3 functions; so do
# ContactBody3D.fmu and ContactBody3D_fmi3.fmu. The two models are fmu_src/ compiled with
# their dimension (fmu_src/variables.hpp: CONTACTBODY_MODEL_DIMENSION). The platform builds
# give the 2D model the solver without the solid-body code (CMakeLists.txt).
set(model_sources fmu_src/fmi2_functions.cpp fmu_src/fmi3_functions.cpp fmu_src/shim.cpp
    fmu_src/instance.cpp fmu_src/model.cpp fmu_src/variables.cpp fmu_src/fmu_state.cpp
    fmu_src/resource_start_values.cpp)
foreach(model dimension IN ZIP_LISTS MODELS MODEL_DIMENSIONS)
  add_library(${model} SHARED ${model_sources})
  target_include_directories(${model} PRIVATE fmu_src ${FMI_HEADERS_DIR})
  target_compile_definitions(${model} PRIVATE CONTACTBODY_MODEL_DIMENSION=${dimension})
  if(CONTACTBODY_FMU_BINARIES_ONLY)  # its own model's variable rows only (fmu_src/variables.cpp)
    target_compile_definitions(${model} PRIVATE CONTACTBODY_ONE_MODEL_TABLE=1)
  endif()
  if(CONTACTBODY_FMU_BINARIES_ONLY AND dimension EQUAL 2)
    target_link_libraries(${model} PRIVATE contactbody_solver_planar)
  else()
    target_link_libraries(${model} PRIVATE contactbody_solver)
  endif()
  make_self_contained(${model})
endforeach()

foreach(companion IN LISTS COMPANIONS)
  add_library(${companion} SHARED system_fmus/companion_fmi2.cpp ${${companion}_model}
              fmu_src/resource_start_values.cpp solver/util/text.cpp solver/util/c_file.cpp)
  target_include_directories(${companion} PRIVATE ${FMI_HEADERS_DIR} fmu_src solver)
  target_compile_definitions(${companion} PRIVATE FMI2_FUNCTION_PREFIX=)
  make_self_contained(${companion})
  # fmi2Functions.h declares the entry points with default visibility (dllexport on Windows).
  # On Linux and Windows the link's export list keeps the rest in; on macOS, whose linker
  # (zig's) takes none, hidden visibility is that list (python_tests/test_portable.py checks).
  if(NOT APPLE)
    set_target_properties(${companion} PROPERTIES CXX_VISIBILITY_PRESET default)
  endif()
endforeach()
