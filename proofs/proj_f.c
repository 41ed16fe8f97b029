/* The projective bound instantiated for binary32 (src/core/cbx_prec.h), a
 * translation unit of its own as proofs/proj.c (jobs P32, PA32, SP32). */
#define CBX_FRAMAC_ONLY_32 1
#define CBX_FLOAT 1
#define CBX_PROJ_LEMMAS 1
#include "cbx_project.c"
