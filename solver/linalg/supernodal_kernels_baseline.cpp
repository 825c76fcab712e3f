// The baseline kernels: compiled as the rest of the solver (linalg/supernodal_kernels.hpp).
#define CONTACTBODY_KERNEL_SET baseline
#define CONTACTBODY_KERNEL_NAME "baseline"
#include "linalg/supernodal_kernels.inc"
