/* A ball under a projective map clipped at a near plane
 * (src/f64/cbx_pball.c) as a translation unit of its own, for Frama-C
 * (jobs PB64, SPB64 of proofs/job.sh): group pball of proofs/fcts.py.  The
 * interval arithmetic it stands on (src/f64/cbx_iv.h) is proven in job
 * T64, the enclosures of src/f64/cbx_paff.h and cbx_pgap.h in job PS64;
 * the lemmas it uses are those of the intervals (CBX_IV_LEMMAS,
 * CBX_IMAT_LEMMAS), of the projected ball (CBX_PSPH_LEMMAS), of the
 * clipped box (CBX_PNEAR_LEMMAS) and its own (CBX_PBALL_LEMMAS), proven in
 * job L64. */
#define CBX_FRAMAC_ONLY_64 1
#define CBX_IMAT_LEMMAS 1
#define CBX_IV_LEMMAS 1
#define CBX_PSPH_LEMMAS 1
#define CBX_PNEAR_LEMMAS 1
#define CBX_PBALL_LEMMAS 1
#include "cbx_pball.c"
