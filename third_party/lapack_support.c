/* The LAPACK auxiliaries that the C form of the LU routines (f2c, third_party/CMakeLists.txt)
   cannot take from reference LAPACK's Fortran: ilaenv and xerbla use the Fortran runtime
   (string comparison, formatted output, STOP), dlamch Fortran 90 intrinsics. The solver calls
   only dgetrf and dgetrs (contact_solver.cpp). f2c's convention: a subroutine returns int. */
#include <float.h>
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
int xerbla_(const char* routine, const int* info, size_t routine_length) {
    (void)routine; (void)info; (void)routine_length;
    return 0;
}

/* DLAMCH of reference LAPACK 3.11 (INSTALL/dlamch.f) for IEEE double: EPSILON(0d0) * 0.5
   (rounding), TINY or 1/HUGE, RADIX, DIGITS, MINEXPONENT, MAXEXPONENT, HUGE. The same values
   as the Fortran's (python_tests/test_lapack_c.py); dgetrf2 asks for 'S' only. */
double dlamch_(const char* cmach, size_t cmach_length) {
    (void)cmach_length;
    const double eps = DBL_EPSILON * 0.5, small = 1.0 / DBL_MAX;
    const double sfmin = small >= DBL_MIN ? small * (1.0 + eps) : DBL_MIN;
    switch (*cmach) {
    case 'E': case 'e': return eps;
    case 'S': case 's': return sfmin;
    case 'B': case 'b': return FLT_RADIX;
    case 'P': case 'p': return eps * FLT_RADIX;
    case 'N': case 'n': return DBL_MANT_DIG;
    case 'R': case 'r': return 1.0;
    case 'M': case 'm': return DBL_MIN_EXP;
    case 'U': case 'u': return DBL_MIN;
    case 'L': case 'l': return DBL_MAX_EXP;
    case 'O': case 'o': return DBL_MAX;
    default: return 0.0;
    }
}
