// The supernodal Cholesky's numeric factorization (linalg/supernodal_cholesky.hpp), compiled once
// for each instruction set it may run on, behind plain types: the baseline of the architecture
// (SSE2 on x86_64, NEON on aarch64), and on x86_64 also x86-64-v3 (AVX2 with FMA). The binary
// picks one set at run time from what the CPU reports (supernodal_kernels()), through a function
// pointer chosen once: ELF ifunc and target_clones do not work with MinGW. Each set's Eigen lives
// in a namespace of its own (its file defines Eigen to another name), so that no inline Eigen
// function compiled for AVX2 can stand in for the baseline's at link time; no Eigen object
// crosses this interface, so their alignments need not agree. docs/decisions.md, "The factor's
// kernels for the CPU it runs on".
#pragma once

#include <cstddef>

namespace contactbody {

// The panels of a supernodal factor: supernode s has columns first[s] .. first[s + 1] - 1 and
// rows row_index[row_start[s] .. row_start[s + 1]) (its columns first), its column-major panel
// at values + value_start[s]; super_of[j] is column j's supernode.
struct SupernodalLayout {
    std::size_t supernodes = 0;
    const int* first = nullptr;
    const int* super_of = nullptr;
    const int* row_start = nullptr;
    const int* row_index = nullptr;
    const std::ptrdiff_t* value_start = nullptr;
};

// Factors the panels in place (they hold P K P^T's lower entries): -1, or the first column (in
// factor order) where K is not positive definite. update: room for the largest panel's rows
// below its columns, squared; local: one int per column.
using FactorPanels = std::ptrdiff_t (*)(const SupernodalLayout& layout, double* values, double* update,
                                        int* local);

struct SupernodalKernels {
    const char* name;  // "baseline" or "x86-64-v3 (AVX2, FMA)"
    FactorPanels factor;
};

// The fastest set this CPU runs, or the baseline (baseline true, or no other set built).
const SupernodalKernels& supernodal_kernels(bool baseline = false);

std::ptrdiff_t factor_panels_baseline(const SupernodalLayout&, double*, double*, int*);
std::ptrdiff_t factor_panels_x86_64_v3(const SupernodalLayout&, double*, double*, int*);

}  // namespace contactbody
