/* The two LAPACK auxiliaries that reference LAPACK writes in Fortran with the Fortran runtime
   (string comparison, formatted output), given in C so that the FMU needs no libgfortran.
   The solver calls only dgetrf and dgetrs (contact_solver.cpp). */
#include <stddef.h>
#include <string.h>

/* ILAENV(1, 'DGETRF', ...): the block size of reference LAPACK 3.11's ilaenv.f for the
   LU factorization (64); dgetrf asks nothing else. */
int ilaenv_(const int* ispec, const char* name, const char* opts, const int* n1, const int* n2,
            const int* n3, const int* n4, size_t name_length, size_t opts_length) {
    (void)opts; (void)n1; (void)n2; (void)n3; (void)n4; (void)opts_length;
    if (*ispec == 1 && name_length >= 6 &&
        (strncmp(name, "DGETRF", 6) == 0 || strncmp(name, "dgetrf", 6) == 0))
        return 64;
    return 1; /* unblocked: correct for any routine, only slower */
}

/* Argument errors: the solver passes valid arguments (and checks INFO), so this is never
   reached; reference XERBLA would print and STOP, which must not happen inside an FMU. */
void xerbla_(const char* routine, const int* info, size_t routine_length) {
    (void)routine; (void)info; (void)routine_length;
}
