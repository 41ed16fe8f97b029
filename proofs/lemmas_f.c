/* The ACSL lemmas of the binary32 family (the binary32 instance of
 * specs/cbx_spec.h, with the shared specs/cbx_logic.h and cbx_ball.h). */
#define CBX_FRAMAC_ONLY_32 1
#define CBX_PROJ_LEMMAS 1
#define CBX_BALL_LEMMAS 1
#include "certbox.h"
