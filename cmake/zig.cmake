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
# -s -fPIC in the compiler command itself, so that CMake's compiler identification, every
# object, host and FMU binary ask zig for one and the same libc++ (stripped, position-independent),
# which zig builds once per target, not once for CMake's checks and again for the binaries.
# -s also drops the debug information zig emits by default: the binaries were stripped anyway,
# and heavy files compile faster without it (docs/building.md, "zig builds its libc++ once per
# set of flags").
set(CMAKE_C_COMPILER "${ZIG}" cc -target ${CONTACTBODY_TARGET} -s -fPIC)
set(CMAKE_CXX_COMPILER "${ZIG}" c++ -target ${CONTACTBODY_TARGET} -s -fPIC)
set(CONTACTBODY_ZIG ON)
