/* The rotation motion (src/f64/cbx_trs.c) as a translation unit of its own,
 * for Frama-C (job T64 of proofs/job.sh): the functions proven so far are
 * the interval arithmetic of src/f64/cbx_iv.h, the rotations,
 * normalisation and arc boxes of src/f64/cbx_quat.h and the cells of
 * src/f64/cbx_cell.h (group trs of
 * proofs/fcts.py).  The interval matrices' lemmas (CBX_IMAT_LEMMAS:
 * iterm_all, bilinearity of a product) are in this unit, as in
 * proofs/imat.c; the normalisation's quotient lemmas (CBX_IV_QUOT_LEMMAS)
 * only here and in proofs/lemmas.c. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_IMAT_LEMMAS 1
#define CBX_IV_LEMMAS 1
#define CBX_IV_QUOT_LEMMAS 1
#include "cbx_trs.c"
