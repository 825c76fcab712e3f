/* What a user would pick instead of our supernodal Cholesky: CHOLMOD's supernodal Cholesky with
 * OpenBLAS on one thread, from Debian's packages (libcholmod3, libopenblas0-serial), in a
 * benchmark only: CHOLMOD's Supernodal module is GPL and never enters an FMU. Built and run by
 * benchmarks/supernodal.py, on the K that bench_supernodal wrote (Matrix Market, lower
 * triangle) and in two orders: CHOLMOD's own choice, and ours (the permutation file, one
 * 0-based index a line: factor position -> unknown). Prints one JSON object: the analysis's
 * seconds, flops and nonzeros, a factorization's seconds (the best of REPEATS), a solve's.
 *   cholmod_supernodal K.mtx PERM.txt [REPEATS]
 */
#include <stdio.h>
#include <stdlib.h>
#include <suitesparse/cholmod.h>
#include <time.h>

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int run(cholmod_sparse* A, int* perm, int repeats, cholmod_common* c, const char* name) {
    c->supernodal = CHOLMOD_SUPERNODAL;
    c->final_ll = 1;
    double t = now();
    cholmod_factor* L = perm ? cholmod_analyze_p(A, perm, NULL, 0, c) : cholmod_analyze(A, c);
    const double analysis = now() - t;
    if (!L) return 1;
    double best = 1e30;
    for (int k = 0; k < repeats; ++k) {
        t = now();
        if (!cholmod_factorize(A, L, c) || c->status != CHOLMOD_OK) return 1;
        if (now() - t < best) best = now() - t;
    }
    cholmod_dense* b = cholmod_ones(A->nrow, 1, CHOLMOD_REAL, c);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, L, b, c);
    cholmod_free_dense(&x, c);
    t = now();
    for (int k = 0; k < 10; ++k) {
        x = cholmod_solve(CHOLMOD_A, L, b, c);
        cholmod_free_dense(&x, c);
    }
    const double solve = (now() - t) / 10;
    printf("\"%s\": {\"analysis_seconds\": %.6g, \"factor_seconds\": %.6g, \"solve_seconds\": %.6g, "
           "\"flops\": %.6g, \"nonzeros\": %.6g, \"gflops\": %.4g, \"ordering\": %d}",
           name, analysis, best, solve, c->fl, c->lnz, c->fl / best * 1e-9, c->selected >= 0
           ? c->method[c->selected].ordering : -1);
    cholmod_free_dense(&b, c);
    cholmod_free_factor(&L, c);
    return 0;
}

int main(int argc, char** argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: cholmod_supernodal K.mtx PERM.txt [REPEATS]\n");
        return 2;
    }
    const int repeats = argc > 3 ? atoi(argv[3]) : 3;
    cholmod_common c;
    cholmod_start(&c);
    FILE* f = fopen(argv[1], "r");
    if (!f) return 2;
    cholmod_sparse* A = cholmod_read_sparse(f, &c);
    fclose(f);
    if (!A || A->stype == 0) {
        fprintf(stderr, "%s: not a symmetric Matrix Market file\n", argv[1]);
        return 2;
    }
    int* perm = malloc(sizeof(int) * A->nrow);
    f = fopen(argv[2], "r");
    for (size_t i = 0; f && i < A->nrow; ++i)
        if (fscanf(f, "%d", &perm[i]) != 1) return 2;
    if (f) fclose(f);
    printf("{\"unknowns\": %zu, ", A->nrow);
    if (run(A, NULL, repeats, &c, "own_order")) return 1;
    printf(", ");
    if (run(A, perm, repeats, &c, "our_order")) return 1;
    printf("}\n");
    free(perm);
    cholmod_free_sparse(&A, &c);
    cholmod_finish(&c);
    return 0;
}
