/*
 * The build the proofs assume (see cbx_ieee_check in certbox.h): every
 * operation rounds once, to nearest, in its own type.  Included by every
 * library source (never by certbox.h: a user's own code may be built as it
 * likes).  What can be refused at compile time is refused here; FMA
 * contraction has no macro in GCC: compile with -ffp-contract=off (or an ISO
 * -std mode), and cbx_ieee_check() catches a build that contracts.
 */
#ifndef CBX_BUILD_H
#define CBX_BUILD_H

#include <float.h>

#if defined(__FAST_MATH__)
#error "certbox: -ffast-math breaks the IEEE semantics its proofs assume"
#endif
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "certbox: -ffinite-math-only: certbox handles infinities and NaN"
#endif
#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "certbox: FLT_EVAL_METHOD must be 0 (x86: use SSE2, -msse2 -mfpmath=sse)"
#endif
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

#endif /* CBX_BUILD_H */
