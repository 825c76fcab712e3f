// The x86-64-v4 kernels (AVX-512 F, DQ, VL and BW beside AVX2 with FMA; CMakeLists.txt compiles
// this file with those flags), with their own Eigen like x86-64-v3's (linalg/supernodal_kernels.hpp).
#define CONTACTBODY_KERNEL_SET x86_64_v4
#define CONTACTBODY_KERNEL_NAME "x86-64-v4 (AVX-512)"
#define Eigen contactbody_eigen_x86_64_v4
#include "linalg/supernodal_kernels.inc"
