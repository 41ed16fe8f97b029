/*
 * branchfree.c: the fast path's wrappers for `make branchfree`
 * (scripts/branchfree.sh).  Compiled twice with the library's flags at
 * -O2: as is (binary64: bf64) and with -DCBX_FLOAT=1, where src/core/cbx_prec.h
 * selects binary32 and the same cbx_fast_box (src/algo/cbx_fast.h) is the
 * binary32 one (bf32).  The script disassembles each wrapper and fails on
 * any conditional branch or call in it.
 */
#include "cbx_fast.h"

#ifdef CBX_FLOAT
#define BF_WRAPPER bf32
#else
#define BF_WRAPPER bf64
#endif

void BF_WRAPPER(const cbx_affine *a, const cbx_box *in, cbx_box *out);
void BF_WRAPPER(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    (void)cbx_fast_box(a, in, out);
}
