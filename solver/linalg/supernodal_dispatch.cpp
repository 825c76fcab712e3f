#include "linalg/supernodal_kernels.hpp"

#if defined(CONTACTBODY_X86_64_KERNELS)
#include <cpuid.h>
#endif

namespace contactbody {

namespace {

#if defined(CONTACTBODY_X86_64_KERNELS)
// x86-64-v3 and x86-64-v4 as the flags these kernels are compiled with ask them, from CPUID and
// what the OS saves (XCR0). Not __builtin_cpu_supports: zig's compiler-rt, which the portable
// Linux and macOS binaries link, answers no to every feature (docs/decisions.md, "The factor's
// kernels for the CPU it runs on"). macOS enables the AVX-512 state on first use, so its XCR0
// shows no ZMM bits and it runs x86-64-v3.
struct X86Levels {
    bool v3 = false, v4 = false;
};

X86Levels x86_levels() {
    unsigned a, b, c, d;
    if (!__get_cpuid(1, &a, &b, &c, &d)) return {};
    const bool fma = c & (1u << 12), osxsave = c & (1u << 27), avx = c & (1u << 28);
    if (!osxsave || !avx) return {};
    unsigned xcr0, xcr0_high;
    __asm__ volatile("xgetbv" : "=a"(xcr0), "=d"(xcr0_high) : "c"(0));
    const bool ymm_saved = (xcr0 & 0x6u) == 0x6u;     // SSE and AVX state
    const bool zmm_saved = (xcr0 & 0xe6u) == 0xe6u;   // and the opmask and ZMM state
    if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return {};
    const bool avx2 = b & (1u << 5);
    const bool avx512 = (b & (1u << 16)) && (b & (1u << 17)) && (b & (1u << 30)) && (b & (1u << 31));  // F DQ BW VL
    X86Levels levels;
    levels.v3 = ymm_saved && avx2 && fma;
    levels.v4 = levels.v3 && zmm_saved && avx512;
    return levels;
}
#endif

// The sets built that this CPU runs, the baseline first.
std::vector<const SupernodalKernels*> sets_this_cpu_runs() {
    std::vector<const SupernodalKernels*> sets{&supernodal_kernels_baseline};
#if defined(CONTACTBODY_X86_64_KERNELS)
    const X86Levels levels = x86_levels();
    if (levels.v3) sets.push_back(&supernodal_kernels_x86_64_v3);
    if (levels.v4) sets.push_back(&supernodal_kernels_x86_64_v4);
#endif
    return sets;
}

}  // namespace

const std::vector<const SupernodalKernels*>& supernodal_kernel_sets() {
    static const std::vector<const SupernodalKernels*> sets = sets_this_cpu_runs();
    return sets;
}

const SupernodalKernels& supernodal_kernels(bool baseline) {
    const auto& sets = supernodal_kernel_sets();
    return baseline ? *sets.front() : *sets.back();
}

}  // namespace contactbody
