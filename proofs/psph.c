/* A ball under a projective map (src/f64/cbx_psph.c) as a translation unit
 * of its own, for Frama-C (jobs PS64, SPS64 of proofs/job.sh): group psph
 * of proofs/fcts.py.  The interval arithmetic it stands on
 * (src/f64/cbx_iv.h) is proven in job T64; the lemmas it uses are those of
 * the ball (CBX_BALL_LEMMAS), of the intervals (CBX_IV_LEMMAS,
 * CBX_IMAT_LEMMAS) and its own (CBX_PSPH_LEMMAS), proven in job L64. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_IMAT_LEMMAS 1
#define CBX_IV_LEMMAS 1
#define CBX_BALL_LEMMAS 1
#define CBX_PSPH_LEMMAS 1
#include "cbx_psph.c"
