#include "linalg/supernodal_kernels.hpp"

namespace contactbody {

namespace {

bool cpu_has_x86_64_v3() {
#if defined(CONTACTBODY_X86_64_V3_KERNELS) && (defined(__x86_64__) || defined(_M_X64))
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

}  // namespace

const SupernodalKernels& supernodal_kernels(bool baseline) {
#if defined(CONTACTBODY_X86_64_V3_KERNELS)
    static const bool has_v3 = cpu_has_x86_64_v3();
    if (!baseline && has_v3) return supernodal_kernels_x86_64_v3;
#endif
    return supernodal_kernels_baseline;
}

}  // namespace contactbody
