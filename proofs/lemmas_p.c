/* The lemmas of the projective bounds of balls and clipped boxes and balls
 * (specs/cbx_psph.h, cbx_pnear.h, cbx_pball.h) and of their binary32 twins
 * (specs/cbx_pwide.h) and of the projected ellipsoid (specs/cbx_pell.h),
 * proven apart from the rest
 * of the binary64 lemmas (job LP64 of proofs/job.sh: only these five
 * files' lemmas are goals, selected by name from the files).  A lemma is
 * proven in the context of every lemma before it in its unit, so these,
 * the last of a long file, took about a second each in proofs/lemmas.c;
 * here they have only the groups they stand on: the ball's (Cauchy-Schwarz)
 * and the intervals'. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_BALL_LEMMAS 1
#define CBX_IV_LEMMAS 1
#define CBX_PSPH_LEMMAS 1
#define CBX_PNEAR_LEMMAS 1
#define CBX_PBALL_LEMMAS 1
#define CBX_PWIDE_LEMMAS 1
#define CBX_PELL_LEMMAS 1
#include "certbox.h"
#include "cbx_iv_logic.h"
