/* An ellipsoid under a projective map (src/f64/cbx_pell.c) as a translation
 * unit of its own, for Frama-C (jobs PE64, SPE64 of proofs/job.sh): group
 * pell of proofs/fcts.py.  It stands on the enclosures of the projected
 * ball (src/f64/cbx_paff.h, cbx_pgap.h, proven in job PS64, their
 * contracts used here) and on the lemmas of the ball (CBX_BALL_LEMMAS),
 * the intervals (CBX_IV_LEMMAS, CBX_IMAT_LEMMAS), the projected ball
 * (CBX_PSPH_LEMMAS) and its own (CBX_PELL_LEMMAS), proven in jobs L64 and
 * LP64. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_IMAT_LEMMAS 1
#define CBX_IV_LEMMAS 1
#define CBX_BALL_LEMMAS 1
#define CBX_PSPH_LEMMAS 1
#define CBX_PELL_LEMMAS 1
#include "cbx_pell.c"
