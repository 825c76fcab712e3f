/* ========================================================================= */
/* === amd_global ========================================================== */
/* ========================================================================= */

/* ------------------------------------------------------------------------- */
/* AMD, Copyright (c) Timothy A. Davis,					     */
/* Patrick R. Amestoy, and Iain S. Duff.  See ../README.txt for License.     */
/* email: DrTimothyAldenDavis@gmail.com                                      */
/* ------------------------------------------------------------------------- */

/* In prior versions of AMD, this file declared the amd_malloc, amd_free,
   amd_realloc, amd_calloc, and amd_printf functions.  They are now replaced
   by functions defined in SuiteSparse_config/SuiteSparse_config.c.
 */
