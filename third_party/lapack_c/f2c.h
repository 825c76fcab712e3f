/* The few f2c types and macros that f2c's translation of reference LAPACK's LU routines uses
   (third_party/README.md). Ours, not libf2c's f2c.h: INTEGER and LOGICAL are C's int (the
   solver calls dgetrf_ with int, as gfortran's INTEGER), and a hidden string length is
   size_t, as gfortran passes it. The translated routines call no libf2c function. */
#ifndef CONTACTBODY_F2C_H
#define CONTACTBODY_F2C_H
#include <stddef.h>
typedef int integer;
typedef int logical;
typedef double doublereal;
typedef size_t ftnlen;
#define TRUE_ (1)
#define FALSE_ (0)
#define abs(x) ((x) >= 0 ? (x) : -(x))
#define min(a, b) ((a) <= (b) ? (a) : (b))
#define max(a, b) ((a) >= (b) ? (a) : (b))
#endif
