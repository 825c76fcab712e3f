/* For python_tests/test_lapack_c.py: dgetrf and dgetrs on random matrices (sizes across the
   blocked path's 64, leading dimensions above the size, entries near underflow where dgetrf2
   divides instead of scaling), their outputs as raw bytes on stdout; then dlamch's ten. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda,
             const int* ipiv, double* b, const int* ldb, int* info, size_t trans_length);
double dlamch_(const char* cmach, size_t cmach_length);

static uint64_t state = 88172645463325252u;
static double uniform(void) {  /* xorshift64: the same numbers everywhere */
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0 - 0.5;
}

int main(void) {
    const int sizes[] = {1, 2, 3, 5, 8, 13, 31, 63, 64, 65, 100, 129, 200};
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; ++k) {
        for (int variant = 0; variant < 3; ++variant) {
            const int n = sizes[k], lda = n + variant, one = 1;
            int info = 0;
            double* a = malloc(sizeof(double) * (size_t)(lda * n));
            double* b = malloc(sizeof(double) * (size_t)n);
            int* pivots = malloc(sizeof(int) * (size_t)n);
            for (int i = 0; i < lda * n; ++i) a[i] = uniform() * (variant == 2 ? 1e-300 : 1.0);
            for (int i = 0; i < n; ++i) b[i] = uniform();
            dgetrf_(&n, &n, a, &lda, pivots, &info);
            fwrite(&info, sizeof info, 1, stdout);
            fwrite(a, sizeof(double), (size_t)(lda * n), stdout);
            fwrite(pivots, sizeof(int), (size_t)n, stdout);
            dgetrs_("N", &n, &one, a, &lda, pivots, b, &n, &info, 1);
            fwrite(&info, sizeof info, 1, stdout);
            fwrite(b, sizeof(double), (size_t)n, stdout);
            free(a);
            free(b);
            free(pivots);
        }
    }
    for (const char* c = "ESBPNRMULOesbpnrmulo"; *c; ++c) {
        const double value = dlamch_(c, 1);
        fwrite(&value, sizeof value, 1, stdout);
    }
    return 0;
}
