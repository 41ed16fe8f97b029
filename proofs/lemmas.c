/* The ACSL lemmas of specs/cbx_spec.h and specs/cbx_ball.h, proven on their own
 * (pass L of proofs/run.sh): this file has no function, so WP's goals are the lemmas. */
#include "certbox.h"

#include "cbx_eft.h"
#include "cbx_tight.h"
