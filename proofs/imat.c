/* The interval-matrix functions (src/f64/cbx_imat.c) as a translation unit of
 * their own, for Frama-C (job I64 of proofs/job.sh): the lemmas of
 * specs/cbx_imat_logic.h are in this unit only (CBX_IMAT_LEMMAS), so the
 * other binary64 goals (proofs/all.c) do not carry them. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_IMAT_LEMMAS 1
#include "cbx_imat.c"
