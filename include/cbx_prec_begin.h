/*
 * The precision of the code that follows: binary64 (CBX_INST == 64) or
 * binary32 (CBX_INST == 32).  The algorithms are written once, for
 * double (src/algo/cbx_interval.c, ...); a binary32 translation unit includes
 * the same text with the type, the constants and the public and logic names
 * below mapped to the float family.  No include guard: certbox.h opens
 * and closes one instance per precision (cbx_prec_end.h undoes this file).
 *
 * Every constant is named by what it is, in units of the format:
 *   u   = 2^-53 (binary64) or 2^-24 (binary32), the unit roundoff;
 *   eta = 2^-1074 or 2^-149, the smallest subnormal;
 * so that |RN(z) - z| <= u |z| + eta for every z in range.  CBX_xxx is the
 * ACSL (real) constant; CBX_K(xxx) the C literal of the same value in the
 * instance's type (exact: every constant is a power of 2 times a short
 * mantissa).
 */
#if !defined(CBX_INST) || (CBX_INST != 64 && CBX_INST != 32)
#error "cbx_prec_begin.h: define CBX_INST as 64 or 32 first"
#endif

#define CBX_K(name) CBX_LIT_(CBX_##name)
#define CBX_C(x) CBX_LIT_(x)     /* a plain literal (0.0, 0.5) in the format */

#if CBX_INST == 64
#define cbx_fp double
#define CBX_LIT_(x) x
#define CBX_LT \lt_double   /* IEEE x < y in ACSL (false with NaN) */
#if defined(__GNUC__)            /* gcc, clang: no <math.h> needed (freestanding) */
#define CBX_HUGE __builtin_huge_val() /* +inf (C99 7.12p3, Annex F)   */
#define CBX_SQRT __builtin_sqrt       /* correctly rounded (F.9.4.5)  */
#else
#define CBX_HUGE HUGE_VAL
#define CBX_SQRT sqrt
#endif
/* relative (units of u = 2^-53) */
#define CBX_U    0x1p-53      /* u                                   */
#define CBX_UP   0x1.00001p-53 /* u (1 + 2^-20): u plus the u^2 terms */
#define CBX_U2   0x1p-52      /* 2u                                  */
#define CBX_U3   0x1.8p-52    /* 3u                                  */
#define CBX_U4   0x1p-51      /* 4u                                  */
#define CBX_U4P  0x1.00001p-51 /* 4u (1 + 2^-20)                     */
#define CBX_U5H  0x1.6p-51    /* 5.5u: the widening factor           */
#define CBX_U8   0x1p-50      /* 8u                                  */
#define CBX_U12  0x1.8p-50    /* 12u: the proven tightness factor    */
#define CBX_U16  0x1p-49      /* 16u                                 */
#define CBX_U80  0x1.4p-47    /* 80u: a ball's proven tightness factor */
/* absolute (units of eta = 2^-1074) */
#define CBX_ETA    0x1p-1074
#define CBX_ETA2   0x1p-1073
#define CBX_ETA4   0x1p-1072
#define CBX_ETA8   0x1p-1071
#define CBX_ETA16  0x1p-1070
#define CBX_ETA64  0x1p-1068
#define CBX_ETA128 0x1p-1067  /* the widening's absolute term        */
#define CBX_ETA256 0x1p-1066
#define CBX_ETA512 0x1p-1065  /* the proven tightness absolute term  */
#define CBX_ETA1024 0x1p-1064 /* a ball's tightness absolute term    */
/* range (the largest finite double is about 2^1024) */
#define CBX_FMAX 0x1.fffffffffffffp1023 /* the largest finite value */
#define CBX_RT   0x1p1018     /* |t| and every product |m c|           */
#define CBX_R19  0x1p1019     /* conversions; sums of two such terms   */
#define CBX_R20  0x1p1020
#define CBX_R21  0x1p1021     /* every partial sum                     */
#define CBX_RW   0x1p968      /* 4u CBX_R19: slack on a computed term magnitude */
/* spheres and ellipsoids */
#define CBX_SB    0x1p509     /* |m_ij| of a sphere row (squares <= RT) */
#define CBX_SR1   0x1p511     /* bound of the rounded square root      */
#define CBX_SR2   0x1p512     /* bound of the radius                   */
#define CBX_STINY 0x1p-300    /* rows below this are rescaled ...      */
#define CBX_SUP   0x1p600     /* ... by this power of 2 ...            */
#define CBX_SDN   0x1p-600    /* ... and their radius scaled back      */
#define CBX_SQE   0x1p-533    /* sqrt of ball_radius's absolute error  */
#define CBX_SA    0x1p-532    /* ball_radius's absolute tightness term */
#define CBX_EB    0x1p254     /* |rot_ij|, |radii_j| of an ellipsoid   */
#define CBX_EP    0x1p508     /* |rot_ij radii_j|                      */
/* projective bounds: a quotient a / b is formed when RN(|a| QS) <= b */
#define CBX_QS    0x1p-1000   /* then |a| <= QR b                      */
#define CBX_QR    0x1p1002
/* The magnitude classes of the domain: |m| <= bm and |c| <= bc with
 * bm bc = 2^1018 (tag, bm, bc); HEAD is tried first. */
#define CBX_CLASS_HEAD(X) X(509, 0x1p509, 0x1p509)
#define CBX_CLASS_TAIL(X) \
  X(0, 0x1p0, 0x1p1018) X(64, 0x1p64, 0x1p954) X(128, 0x1p128, 0x1p890) \
  X(192, 0x1p192, 0x1p826) X(256, 0x1p256, 0x1p762) X(320, 0x1p320, 0x1p698) \
  X(384, 0x1p384, 0x1p634) X(448, 0x1p448, 0x1p570) X(512, 0x1p512, 0x1p506) \
  X(576, 0x1p576, 0x1p442) X(640, 0x1p640, 0x1p378) X(704, 0x1p704, 0x1p314) \
  X(768, 0x1p768, 0x1p250) X(832, 0x1p832, 0x1p186) X(896, 0x1p896, 0x1p122) \
  X(960, 0x1p960, 0x1p58) X(1018, 0x1p1018, 0x1p0)

#else /* CBX_INST == 32 */
#define cbx_fp float
#define CBX_LT \lt_float
#if defined(__GNUC__)
#define CBX_HUGE __builtin_huge_valf()
#define CBX_SQRT __builtin_sqrtf
#else
#define CBX_HUGE HUGE_VALF
#define CBX_SQRT sqrtf
#endif
#define CBX_LIT_(x) CBX_LIT2_(x)
#define CBX_LIT2_(x) x##f
/* relative (units of u = 2^-24) */
#define CBX_U    0x1p-24
#define CBX_UP   0x1.00001p-24
#define CBX_U2   0x1p-23
#define CBX_U3   0x1.8p-23
#define CBX_U4   0x1p-22
#define CBX_U4P  0x1.00001p-22
#define CBX_U5H  0x1.6p-22
#define CBX_U8   0x1p-21
#define CBX_U12  0x1.8p-21
#define CBX_U16  0x1p-20
#define CBX_U80  0x1.4p-18
/* absolute (units of eta = 2^-149) */
#define CBX_ETA    0x1p-149
#define CBX_ETA2   0x1p-148
#define CBX_ETA4   0x1p-147
#define CBX_ETA8   0x1p-146
#define CBX_ETA16  0x1p-145
#define CBX_ETA64  0x1p-143
#define CBX_ETA128 0x1p-142
#define CBX_ETA256 0x1p-141
#define CBX_ETA512 0x1p-140
#define CBX_ETA1024 0x1p-139
/* range (the largest finite float is about 2^128) */
#define CBX_FMAX 0x1.fffffep127
#define CBX_RT   0x1p122
#define CBX_R19  0x1p123
#define CBX_R20  0x1p124
#define CBX_R21  0x1p125
#define CBX_RW   0x1p101     /* 4u CBX_R19 */
/* spheres and ellipsoids */
#define CBX_SB    0x1p61
#define CBX_SR1   0x1p63
#define CBX_SR2   0x1p64
#define CBX_STINY 0x1p-30
#define CBX_SUP   0x1p90
#define CBX_SDN   0x1p-90
#define CBX_SQE   0x1p-71
#define CBX_SA    0x1p-70
#define CBX_EB    0x1p30
#define CBX_EP    0x1p60
#define CBX_QS    0x1p-120
#define CBX_QR    0x1p122
/* magnitude classes: bm bc = 2^122 */
#define CBX_CLASS_HEAD(X) X(f61, 0x1p61, 0x1p61)
#define CBX_CLASS_TAIL(X) \
  X(f0, 0x1p0, 0x1p122) X(f8, 0x1p8, 0x1p114) X(f16, 0x1p16, 0x1p106) \
  X(f24, 0x1p24, 0x1p98) X(f32, 0x1p32, 0x1p90) X(f40, 0x1p40, 0x1p82) \
  X(f48, 0x1p48, 0x1p74) X(f56, 0x1p56, 0x1p66) X(f64, 0x1p64, 0x1p58) \
  X(f72, 0x1p72, 0x1p50) X(f80, 0x1p80, 0x1p42) X(f88, 0x1p88, 0x1p34) \
  X(f96, 0x1p96, 0x1p26) X(f104, 0x1p104, 0x1p18) X(f112, 0x1p112, 0x1p10) \
  X(f120, 0x1p120, 0x1p2) X(f122, 0x1p122, 0x1p0)

/* The float family's names: public types and functions end in f, the
 * logic (specs/cbx_spec.h, specs/cbx_ball.h) and the trusted C helpers in
 * _f, so that both families can be declared (and specified) in one
 * translation unit. */
#define cbx_affine cbx_affinef
#define cbx_box cbx_boxf
#define cbx_cbox cbx_cboxf
#define cbx_transform_box cbx_transform_boxf
#define cbx_transform_boxes cbx_transform_boxesf
#define cbx_prepared cbx_preparedf
#define cbx_prepare cbx_preparef
#define cbx_transform_box_prep cbx_transform_box_prepf
#define cbx_transform_boxes_prep cbx_transform_boxes_prepf
#define cbx_transform_cbox cbx_transform_cboxf
#define cbx_box_to_cbox cbx_box_to_cboxf
#define cbx_cbox_to_box cbx_cbox_to_boxf
#define cbx_sphere_box cbx_sphere_boxf
#define cbx_ellipsoid_box cbx_ellipsoid_boxf
#define cbx_affine2 cbx_affine2f
#define cbx_box2 cbx_box2f
#define cbx_cbox2 cbx_cbox2f
#define cbx_transform_cbox2 cbx_transform_cbox2f
#define cbx_box2_to_cbox2 cbx_box2_to_cbox2f
#define cbx_cbox2_to_box2 cbx_cbox2_to_box2f
#define cbx_transform_box2 cbx_transform_box2f
#define cbx_disk_box2 cbx_disk_box2f
#define cbx_ellipse_box2 cbx_ellipse_box2f
#define cbx_proj cbx_projf
#define cbx_project_box cbx_project_boxf
#define cbx_pinf cbx_pinf_f
#define cbx_ninf cbx_ninf_f
#define cbx_sqrt_rn cbx_sqrt_rn_f
#define cbx_div_rn cbx_div_rn_f
#include "cbx_names_f.h"
#endif
