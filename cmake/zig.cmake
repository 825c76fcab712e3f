# What the zig toolchain files share (included by them after setting CMAKE_SYSTEM_PROCESSOR and
# CONTACTBODY_TARGET): zig's clang with its own glibc stubs and libc++ linked in (ziglang from
# PyPI, pinned in requirements.txt). ZIG: path of the zig executable (the top-level build
# passes it; else zig on PATH).
# CONTACTBODY_SYSTEM_NAME: Linux unless the toolchain file says Darwin.
if(NOT CONTACTBODY_SYSTEM_NAME)
  set(CONTACTBODY_SYSTEM_NAME Linux)
endif()
set(CMAKE_SYSTEM_NAME ${CONTACTBODY_SYSTEM_NAME})
if(NOT ZIG)
  find_program(ZIG zig REQUIRED)
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ZIG)
set(CMAKE_C_COMPILER "${ZIG}" cc -target ${CONTACTBODY_TARGET})
set(CMAKE_CXX_COMPILER "${ZIG}" c++ -target ${CONTACTBODY_TARGET})
set(CONTACTBODY_ZIG ON)
