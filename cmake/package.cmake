# Packages ContactBody.fmu (FMI 2.0), ContactBody_fmi3.fmu (FMI 3.0), their 3D model's
# ContactBody3D.fmu and ContactBody3D_fmi3.fmu, BeltDrive.fmu and Press.fmu. With CONTACTBODY_PORTABLE (the
# default: what users get) their binaries come from this project built again for each platform
# with a toolchain from cmake/: linux64 and aarch64-linux by zig (glibc 2.17), macOS x86_64 and
# arm64 by zig (macOS 11), win64 by MinGW-w64. Without it
# (the sanitizer job) the FMU holds the native build's linux64 binary only.
# The modelDescriptions are written by native tools from the variable tables.

foreach(model dimension IN ZIP_LISTS MODELS MODEL_DIMENSIONS)
  add_executable(${model}_model_description fmu_src/generate_model_description.cpp fmu_src/variables.cpp)
  target_include_directories(${model}_model_description PRIVATE fmu_src)
  target_compile_definitions(${model}_model_description PRIVATE CONTACTBODY_MODEL_DIMENSION=${dimension})
  target_link_libraries(${model}_model_description PRIVATE contactbody_solver)
endforeach()
foreach(companion IN LISTS COMPANIONS)
  add_executable(${companion}_model_description system_fmus/generate_model_description.cpp
                 ${${companion}_model})
endforeach()

set(fmus ${MODELS} ${COMPANIONS})
set(licenses ${PROJECT_SOURCE_DIR}/LICENSE)
# The platform table (platforms.json): name, FMI 2.0 folder, FMI 3.0 tuple, toolchain file,
# library suffix, the hosts built for it, the licences of the runtime linked in. Each row's
# binaries go to FMI 3.0's folder of its tuple; rows that share an FMI 2.0 folder (darwin64)
# are joined there into one universal binary.
file(READ ${PROJECT_SOURCE_DIR}/platforms.json platform_table)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/platforms.json)
string(JSON platform_count LENGTH ${platform_table} platforms)
math(EXPR platform_last "${platform_count} - 1")
if(CONTACTBODY_PORTABLE)
  include(ExternalProject)
  # The platforms' builds run beside each other and the native targets, each on two jobs, so
  # that no core idles at a build's tail; cmake/build_platform.cmake builds a failed one once
  # more (docs/building.md, "CI time").
  if(NOT ZIG)  # scripts/setup.sh passes a zig outside the clone (its libc++ builds are cached by path)
    python_package_file(ZIG ziglang zig)
  endif()
  get_filename_component(ZIG_LIB ${ZIG} DIRECTORY)
  set(license_names LICENSE)
  foreach(i RANGE ${platform_last})
    string(JSON platform GET ${platform_table} platforms ${i} name)
    string(JSON fmi2_folder GET ${platform_table} platforms ${i} fmi2_folder)
    string(JSON tuple GET ${platform_table} platforms ${i} fmi3_tuple)
    string(JSON toolchain GET ${platform_table} platforms ${i} toolchain)
    string(JSON suffix GET ${platform_table} platforms ${i} library_suffix)
    string(JSON host_count LENGTH ${platform_table} platforms ${i} hosts)
    set(hosts)
    if(host_count GREATER 0)
      math(EXPR host_last "${host_count} - 1")
      foreach(h RANGE ${host_last})
        string(JSON host GET ${platform_table} platforms ${i} hosts ${h})
        list(APPEND hosts ${host})
      endforeach()
    endif()
    string(JSON runtime_count LENGTH ${platform_table} platforms ${i} runtime_licenses)
    if(runtime_count GREATER 0)
      math(EXPR runtime_last "${runtime_count} - 1")
      foreach(r RANGE ${runtime_last})
        string(JSON license_name MEMBER ${platform_table} platforms ${i} runtime_licenses ${r})
        string(JSON license_path GET ${platform_table} platforms ${i} runtime_licenses ${license_name})
        string(REPLACE "\${ZIG_LIB}" "${ZIG_LIB}" license_path "${license_path}")
        if(NOT license_name IN_LIST license_names)  # zig's libc++ serves two platforms
          list(APPEND licenses ${license_path})
          list(APPEND license_names ${license_name})
        endif()
      endforeach()
    endif()
    set(dir ${CMAKE_BINARY_DIR}/${platform})
    set(products)
    if(NOT fmi2_folder IN_LIST fmi2_folders)
      list(APPEND fmi2_folders ${fmi2_folder})
      set(fmi2_suffix_${fmi2_folder} ${suffix})
    endif()
    foreach(fmu IN LISTS fmus)
      list(APPEND products ${dir}/${fmu}${suffix})
      list(APPEND ${fmu}_fmi3_binaries ${tuple} ${dir}/${fmu}${suffix})
      list(APPEND ${fmu}_slices_${fmi2_folder} ${dir}/${fmu}${suffix})
    endforeach()
    string(REPLACE ";" "|" hosts_arg "${hosts}")
    ExternalProject_Add(binaries_${platform}
      SOURCE_DIR ${PROJECT_SOURCE_DIR} BINARY_DIR ${dir}
      LIST_SEPARATOR |
      CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/${toolchain}
                 -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} -DCONTACTBODY_FMU_BINARIES_ONLY=ON
                 -DCONTACTBODY_HOSTS=${hosts_arg}
                 -DZIG=${ZIG} -DEIGEN3_INCLUDE_DIR=${EIGEN3_INCLUDE_DIR}
      BUILD_COMMAND ${CMAKE_COMMAND} -DDIR=<BINARY_DIR> -P ${PROJECT_SOURCE_DIR}/cmake/build_platform.cmake
      INSTALL_COMMAND "" BUILD_ALWAYS ON BUILD_BYPRODUCTS ${products})
    list(APPEND binary_targets binaries_${platform})
  endforeach()
  # FMI 2.0's folders: one binary each, a universal one where rows share the folder.
  foreach(fmi2_folder IN LISTS fmi2_folders)
    foreach(fmu IN LISTS fmus)
      set(slices ${${fmu}_slices_${fmi2_folder}})
      list(LENGTH slices slice_count)
      if(slice_count EQUAL 1)
        list(APPEND ${fmu}_binaries ${fmi2_folder} ${slices})
      else()
        find_program(LLVM_LIPO NAMES llvm-lipo-14 llvm-lipo REQUIRED)  # Debian's llvm-14
        set(universal ${CMAKE_BINARY_DIR}/${fmi2_folder}/${fmu}${fmi2_suffix_${fmi2_folder}})
        add_custom_command(OUTPUT ${universal}
          COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/${fmi2_folder}
          COMMAND ${LLVM_LIPO} -create -output ${universal} ${slices}
          DEPENDS ${slices} ${binary_targets}
          COMMENT "Joining ${fmu}'s ${fmi2_folder} binary (${slice_count} architectures)")
        list(APPEND ${fmu}_binaries ${fmi2_folder} ${universal})
      endif()
    endforeach()
  endforeach()
else()
  # The native build's binary, in the table's first platform's folders (linux64).
  include(cmake/fmu_binaries.cmake)
  string(JSON native GET ${platform_table} platforms 0 fmi2_folder)
  string(JSON native_tuple GET ${platform_table} platforms 0 fmi3_tuple)
  foreach(fmu IN LISTS fmus)
    set(${fmu}_binaries ${native} $<TARGET_FILE:${fmu}>)
    set(${fmu}_fmi3_binaries ${native_tuple} $<TARGET_FILE:${fmu}>)
    list(APPEND binary_targets ${fmu})
  endforeach()
  set(license_names LICENSE)
endif()

# add_fmu(NAME GENERATOR target [GENERATOR_ARGS args] BINARIES platform file ...
#         LICENSES files LICENSE_NAMES names): one .fmu in the build folder. No sources/: a
# source FMU that an importer could compile would need Eigen (C++) and the SuiteSparse subset,
# which fmpy's compile step (C only) cannot build, and FMI 3.0 ties sources/ to a buildDescription.xml; the sources are this repository
# (docs/building.md).
function(add_fmu name)
  cmake_parse_arguments(FMU "" "GENERATOR" "GENERATOR_ARGS;BINARIES;LICENSES;LICENSE_NAMES;DEPENDS;RESOURCES" ${ARGN})
  set(dir ${CMAKE_BINARY_DIR}/fmu/${name})
  set(file ${CMAKE_BINARY_DIR}/${name}.fmu)
  set(commands)
  set(binary_files)
  while(FMU_BINARIES)
    list(POP_FRONT FMU_BINARIES platform binary)
    list(APPEND binary_files ${binary})
    list(APPEND commands COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}/binaries/${platform}
                         COMMAND ${CMAKE_COMMAND} -E copy ${binary} ${dir}/binaries/${platform}/)
  endwhile()
  foreach(resource IN LISTS FMU_RESOURCES)
    list(APPEND commands COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}/resources
                         COMMAND ${CMAKE_COMMAND} -E copy ${resource} ${dir}/resources/)
  endforeach()
  foreach(license IN ZIP_LISTS FMU_LICENSES FMU_LICENSE_NAMES)
    list(APPEND commands COMMAND ${CMAKE_COMMAND} -E copy ${license_0}
                         ${dir}/documentation/licenses/${license_1})
  endforeach()
  add_custom_command(OUTPUT ${file}
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${dir}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}/documentation/licenses
    COMMAND ${FMU_GENERATOR} ${FMU_GENERATOR_ARGS} ${dir}/modelDescription.xml
    ${commands}
    COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/cmake/pack_fmu.py ${dir} ${file}
    DEPENDS ${PROJECT_SOURCE_DIR}/cmake/pack_fmu.py ${FMU_GENERATOR} ${FMU_DEPENDS} ${binary_files} ${FMU_LICENSES} ${FMU_RESOURCES}
    COMMENT "Packaging ${name}.fmu")
  add_custom_target(${name}_fmu ALL DEPENDS ${file})
endfunction()

# ContactBody links SuiteSparse, METIS, Eigen and Spectra in: their licences too.
set(SS ${PROJECT_SOURCE_DIR}/third_party/SuiteSparse-5.12.0)
set(contactbody_licenses ${licenses}
    ${SS}/CHOLMOD/Doc/License.txt ${SS}/CHOLMOD/Core/lesser.txt ${SS}/AMD/Doc/License.txt
    ${SS}/CAMD/Doc/License.txt ${SS}/COLAMD/Doc/License.txt ${SS}/CCOLAMD/Doc/License.txt
    ${SS}/LICENSE.txt ${SS}/metis-5.1.0/LICENSE.txt
    /usr/share/common-licenses/MPL-2.0
    ${PROJECT_SOURCE_DIR}/third_party/spectra-1.0.1/LICENSE
    ${PROJECT_SOURCE_DIR}/third_party/spectra-1.0.1/COPYRIGHT
    ${PROJECT_SOURCE_DIR}/third_party/README.md)
set(contactbody_license_names ${license_names}
    CHOLMOD-License.txt CHOLMOD-LGPL-2.1.txt AMD-License.txt CAMD-License.txt COLAMD-License.txt
    CCOLAMD-License.txt SuiteSparse-LICENSE.txt METIS-LICENSE.txt
    Eigen-MPL-2.0.txt Spectra-MPL-2.0.txt Spectra-COPYRIGHT.txt README.md)
# Each model's FMI 2.0 FMU, and its FMI 3.0 FMU: the same binaries under FMI 3.0's platform
# tuples. The 3D model carries its default body (the rectangle is 2D).
set(ContactBody_resources)
set(ContactBody3D_resources ${PROJECT_SOURCE_DIR}/fmu_src/resources3d/block.msh)
foreach(model IN LISTS MODELS)
  add_fmu(${model} GENERATOR ${model}_model_description BINARIES ${${model}_binaries}
          LICENSES ${contactbody_licenses} LICENSE_NAMES ${contactbody_license_names}
          RESOURCES ${${model}_resources} DEPENDS ${binary_targets})
  add_fmu(${model}_fmi3 GENERATOR ${model}_model_description GENERATOR_ARGS --fmi3
          BINARIES ${${model}_fmi3_binaries} LICENSES ${contactbody_licenses}
          LICENSE_NAMES ${contactbody_license_names} RESOURCES ${${model}_resources}
          DEPENDS ${binary_targets})
endforeach()
foreach(companion IN LISTS COMPANIONS)
  add_fmu(${companion} GENERATOR ${companion}_model_description BINARIES ${${companion}_binaries}
          LICENSES ${licenses} LICENSE_NAMES ${license_names} DEPENDS ${binary_targets})
endforeach()
