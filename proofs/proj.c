/* The projective bound (src/algo/cbx_project.c, with the quotients of
 * src/core/cbx_quot.h) as a binary64 translation unit of its own, for
 * Frama-C (jobs P64, PA64, SP64 of proofs/job.sh): the lemmas of
 * specs/cbx_proj_logic.h and specs/cbx_proj.h are in this unit only
 * (CBX_PROJ_LEMMAS), so the other binary64 goals (proofs/all.c) do not
 * carry them. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_PROJ_LEMMAS 1
#include "cbx_project.c"
