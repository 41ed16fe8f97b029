/* The binary64 library as one translation unit, for Frama-C: the static
 * inline primitives of the internal headers then exist (and are proven)
 * once.  CBX_FRAMAC_ONLY_64 keeps the binary32 logic out of the provers'
 * context (certbox.h). */
#define CBX_FRAMAC_ONLY_64 1
#include "cbx_interval.c"
#include "cbx_center.c"
#include "cbx_convert.c"
#include "cbx_status.c"
#include "cbx_sphere.c"
#include "cbx_batch.c"
#include "cbx_tight.c"
#include "cbx_class.c"
#include "cbx_motion.c"
#include "cbx_chain.c"
