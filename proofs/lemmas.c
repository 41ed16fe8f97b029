/* The ACSL lemmas of the binary64 family (specs/cbx_logic.h, cbx_ball.h,
 * the binary64 instance of cbx_spec.h, cbx_class.h, cbx_iv_logic.h, cbx_quat_logic.h, cbx_psph.h, cbx_pnear.h), proven on their own
 * (pass L of proofs/run.sh): this file has no function, so WP's goals are
 * the lemmas. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_IMAT_LEMMAS 1
#define CBX_BALL_LEMMAS 1
#define CBX_MOTION_LEMMAS 1
#define CBX_CHAIN_LEMMAS 1
#define CBX_PROJ_LEMMAS 1
#define CBX_IV_LEMMAS 1
#define CBX_PSPH_LEMMAS 1
#define CBX_PNEAR_LEMMAS 1
#include "certbox.h"
#include "cbx_iv_logic.h"
#include "cbx_quat_logic.h"

#include "cbx_eft.h"
#include "cbx_tight.h"
