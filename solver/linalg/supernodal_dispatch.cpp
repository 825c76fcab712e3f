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
    static const SupernodalKernels base{"baseline", &factor_panels_baseline};
#if defined(CONTACTBODY_X86_64_V3_KERNELS)
    static const SupernodalKernels v3{"x86-64-v3 (AVX2, FMA)", &factor_panels_x86_64_v3};
    static const bool has_v3 = cpu_has_x86_64_v3();
    if (!baseline && has_v3) return v3;
#endif
    return base;
}

}  // namespace contactbody
