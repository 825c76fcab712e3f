# Linux x86_64 binaries that load with glibc 2.17 and later: zig's clang with its own glibc
# 2.17 stubs and libc++ linked in (ziglang from PyPI, pinned in requirements.txt).
# ZIG: path of the zig executable (the top-level build passes it; else zig on PATH).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CONTACTBODY_TARGET x86_64-linux-gnu.2.17)
if(NOT ZIG)
  find_program(ZIG zig REQUIRED)
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ZIG)
set(CMAKE_C_COMPILER "${ZIG}" cc -target ${CONTACTBODY_TARGET})
set(CMAKE_CXX_COMPILER "${ZIG}" c++ -target ${CONTACTBODY_TARGET})
# LAPACK's Fortran: plain gfortran objects (no Fortran runtime is called, see third_party/).
set(CMAKE_Fortran_COMPILER gfortran)
set(CONTACTBODY_ZIG ON)
