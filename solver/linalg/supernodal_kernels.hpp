// The supernodal Cholesky's dense kernels (linalg/supernodal_cholesky.hpp), compiled once for
// each instruction set they may run on, behind plain types: the baseline of the architecture
// (SSE2 on x86_64, NEON on aarch64), and on x86_64 also x86-64-v3 (AVX2 with FMA) and x86-64-v4
// (AVX-512). The binary picks one set at run time from what the CPU reports (supernodal_kernels()), through function
// pointers chosen once: ELF ifunc and target_clones do not work with MinGW. Each set's Eigen lives
// in a namespace of its own (its file defines Eigen to another name), so that no inline Eigen
// function compiled for AVX2 can stand in for the baseline's at link time; no Eigen object
// crosses this interface, so their alignments need not agree. docs/decisions.md, "The factor's
// kernels for the CPU it runs on".
#pragma once

#include <cstddef>
#include <vector>

namespace contactbody {

// Column-major blocks: a pointer to the first entry and the leading dimension (ld).
struct SupernodalKernels {
    const char* name;  // "baseline", "x86-64-v3 (AVX2, FMA)" or "x86-64-v4 (AVX-512)"
    // The n x n lower block a in place of its Cholesky factor: -1, or the column where it is
    // not positive definite (Eigen's blocked LLT).
    std::ptrdiff_t (*cholesky)(double* a, std::ptrdiff_t n, std::ptrdiff_t ld);
    // x <- x L^-T: x rows x n, L the n x n lower block l (a triangular solve on the right).
    void (*solve_right)(const double* l, std::ptrdiff_t n, std::ptrdiff_t ldl, double* x, std::ptrdiff_t rows,
                        std::ptrdiff_t ldx);
    // c = a a^T, its lower triangle only (a rows x depth, c rows x rows: SYRK).
    void (*lower_product)(const double* a, std::ptrdiff_t lda, std::ptrdiff_t rows, std::ptrdiff_t depth,
                          double* c, std::ptrdiff_t ldc);
    // c = a b^T (a rows x depth, b cols x depth, c rows x cols: GEMM).
    void (*product)(const double* a, std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb,
                    std::ptrdiff_t rows, std::ptrdiff_t cols, std::ptrdiff_t depth, double* c,
                    std::ptrdiff_t ldc);
    // The n x n block a in place of its LU factor without pivoting (L unit lower below the
    // diagonal, U upper on and above it): -1, or the column whose pivot is not above 1e-12
    // times the largest entry of what is left of its column.
    std::ptrdiff_t (*lu)(double* a, std::ptrdiff_t n, std::ptrdiff_t ld);
    // c -= a b^T (the same shapes).
    void (*subtract_product)(const double* a, std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb,
                             std::ptrdiff_t rows, std::ptrdiff_t cols, std::ptrdiff_t depth, double* c,
                             std::ptrdiff_t ldc);
    // A supernode's part of a solve with its panel l (rows x n, ld = rows: its n x n lower
    // block, then the rows below): forward, y <- L^-1 y (n entries), then g = below y
    // (rows - n entries); backward, y <- L^-T (y - below^T g).
    void (*forward_panel)(const double* l, std::ptrdiff_t rows, std::ptrdiff_t n, double* y, double* g);
    void (*backward_panel)(const double* l, std::ptrdiff_t rows, std::ptrdiff_t n, double* y, const double* g);
};

// The sets built that this CPU runs: the baseline first, the fastest last.
const std::vector<const SupernodalKernels*>& supernodal_kernel_sets();
// The fastest set this CPU runs, or the baseline (baseline true, or no other set built).
const SupernodalKernels& supernodal_kernels(bool baseline = false);

extern const SupernodalKernels supernodal_kernels_baseline;
extern const SupernodalKernels supernodal_kernels_x86_64_v3;
extern const SupernodalKernels supernodal_kernels_x86_64_v4;

}  // namespace contactbody
