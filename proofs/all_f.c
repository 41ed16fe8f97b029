/* The binary32 family as one translation unit, for Frama-C: the same
 * sources as proofs/all.c instantiated for float (src/core/cbx_prec.h), alone
 * in the provers' context (CBX_FRAMAC_ONLY_32). */
#define CBX_FRAMAC_ONLY_32 1
#define CBX_FLOAT 1
#include "cbx_interval.c"
#include "cbx_center.c"
#include "cbx_convert.c"
#include "cbx_sphere.c"
#include "cbx_batch.c"
