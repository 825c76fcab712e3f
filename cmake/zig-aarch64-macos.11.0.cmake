# macOS arm64 binaries (macOS 11 and later, Apple silicon): zig's clang against zig's
# libSystem stubs, libc++ linked in (cmake/zig.cmake), ad-hoc signed by zig's linker as arm64
# macOS requires. No contraction into fused multiply-adds and Eigen's NEON code made to round
# as its SSE2 code, as for aarch64 Linux (cmake/zig-aarch64-linux-gnu.2.17.cmake). Cross-built
# and checked here, never run: there is no macOS.
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CONTACTBODY_TARGET aarch64-macos.11.0)
set(CONTACTBODY_SYSTEM_NAME Darwin)
include(${CMAKE_CURRENT_LIST_DIR}/zig.cmake)
set(CMAKE_C_FLAGS_INIT -ffp-contract=off)
set(CMAKE_CXX_FLAGS_INIT -ffp-contract=off)
