// The x86-64-v3 kernels (AVX2 with FMA; CMakeLists.txt compiles this file with -mavx2 -mfma),
// with their own Eigen: no inline function of it may replace the baseline's at link time
// (linalg/supernodal_kernels.hpp).
#define CONTACTBODY_KERNEL_SET x86_64_v3
#define CONTACTBODY_KERNEL_NAME "x86-64-v3 (AVX2, FMA)"
#define Eigen contactbody_eigen_x86_64_v3
#include "linalg/supernodal_kernels.inc"
