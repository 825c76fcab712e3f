# Linux aarch64 binaries that load with glibc 2.17 and later: zig's clang with its own glibc
# 2.17 stubs and libc++ linked in (cmake/zig.cmake), as for x86_64. Bit for bit with linux64,
# which has no fused multiply-add (baseline x86_64): nothing contracts a * b + c into one
# (clang does where the target has FMA, as every AArch64 does), and Eigen's NEON code is made
# to round as its SSE2 code (cmake/eigen_like_x86_64.cmake, applied by CMakeLists.txt for
# this processor).
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CONTACTBODY_TARGET aarch64-linux-gnu.2.17)
include(${CMAKE_CURRENT_LIST_DIR}/zig.cmake)
set(CMAKE_C_FLAGS_INIT -ffp-contract=off)
set(CMAKE_CXX_FLAGS_INIT -ffp-contract=off)
