/* The ACSL lemmas of the binary64 family (specs/cbx_logic.h, cbx_ball.h,
 * the binary64 instance of cbx_spec.h, cbx_class.h, cbx_iv_logic.h,
 * cbx_quat_logic.h), proven on their own (job L64 of proofs/job.sh): this
 * file has no function, so WP's goals are the lemmas.  Those of the
 * projective balls and clipped bounds (cbx_psph.h, cbx_pnear.h,
 * cbx_pball.h) are proven in proofs/lemmas_p.c (job LP64). */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_IMAT_LEMMAS 1
#define CBX_BALL_LEMMAS 1
#define CBX_MOTION_LEMMAS 1
#define CBX_CHAIN_LEMMAS 1
#define CBX_PROJ_LEMMAS 1
#define CBX_IV_LEMMAS 1
#define CBX_IV_QUOT_LEMMAS 1
#include "certbox.h"
#include "cbx_iv_logic.h"
#include "cbx_quat_logic.h"

#include "cbx_eft.h"
#include "cbx_tight.h"
