# macOS x86_64 binaries (macOS 11 and later): zig's clang against zig's libSystem stubs, libc++
# linked in (cmake/zig.cmake). Cross-built and checked here, never run: there is no macOS.
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CONTACTBODY_TARGET x86_64-macos.11.0)
set(CONTACTBODY_SYSTEM_NAME Darwin)
include(${CMAKE_CURRENT_LIST_DIR}/zig.cmake)
