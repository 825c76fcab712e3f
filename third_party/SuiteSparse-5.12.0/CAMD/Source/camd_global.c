/* ========================================================================= */
/* === camd_global ========================================================= */
/* ========================================================================= */

/* ------------------------------------------------------------------------- */
/* CAMD, Copyright (c) Timothy A. Davis, Yanqing Chen,			     */
/* Patrick R. Amestoy, and Iain S. Duff.  See ../README.txt for License.     */
/* email: DrTimothyAldenDavis@gmail.com                                      */
/* ------------------------------------------------------------------------- */

/* In prior versions of CAMD, this file declared the camd_malloc, camd_free,
   camd_realloc, camd_calloc, and camd_printf functions.  They are now replaced
   by functions defined in SuiteSparse_config/SuiteSparse_config.c.
 */
