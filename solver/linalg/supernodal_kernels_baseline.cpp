// The baseline kernels: compiled as the rest of the solver (linalg/supernodal_kernels.hpp).
#define CONTACTBODY_KERNEL_SET baseline
#include "linalg/supernodal_kernels.inc"
