/* The binary32 twins of the binary64-only projective bounds
 * (src/f32/cbx_pwide.c) as a translation unit of their own, for Frama-C
 * (jobs PW, SPW of proofs/job.sh): group pwide of proofs/fcts.py.  Both
 * families' logic is in it (the twins take float inputs and call the
 * binary64 functions, whose contracts they stand on: proven in jobs PS64,
 * PN64, PB64); the lemmas of specs/cbx_pwide.h (CBX_PWIDE_LEMMAS) are
 * proven in job LP64. */
#define CBX_PWIDE_LEMMAS 1
#include "../src/f32/cbx_pwide.c" /* src/f32 is no include folder */
