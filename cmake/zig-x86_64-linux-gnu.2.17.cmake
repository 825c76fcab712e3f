# Linux x86_64 binaries that load with glibc 2.17 and later: zig's clang with its own glibc
# 2.17 stubs and libc++ linked in (cmake/zig.cmake).
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CONTACTBODY_TARGET x86_64-linux-gnu.2.17)
include(${CMAKE_CURRENT_LIST_DIR}/zig.cmake)
