/*
 * Closes the precision instance opened by cbx_prec_begin.h: every macro it
 * defined is removed, so the code after it (and a user's code after
 * certbox.h) sees none of them.  No include guard.
 */
#if CBX_INST == 32
#undef cbx_affine
#undef cbx_box
#undef cbx_cbox
#undef cbx_transform_box
#undef cbx_transform_boxes
#undef cbx_prepared
#undef cbx_prepare
#undef cbx_transform_box_prep
#undef cbx_transform_boxes_prep
#undef cbx_transform_cbox
#undef cbx_box_to_cbox
#undef cbx_cbox_to_box
#undef cbx_sphere_box
#undef cbx_ellipsoid_box
#undef cbx_pinf
#undef cbx_ninf
#undef cbx_sqrt_rn
#define CBX_NAMES_UNDEF
#include "cbx_names_f.h"
#undef CBX_NAMES_UNDEF
#undef CBX_LIT2_
#endif
#undef cbx_fp
#undef CBX_LT
#undef CBX_HUGE
#undef CBX_SQRT
#undef CBX_C
#undef CBX_K
#undef CBX_LIT_
#undef CBX_U
#undef CBX_UP
#undef CBX_U2
#undef CBX_U3
#undef CBX_U4
#undef CBX_U4P
#undef CBX_U5H
#undef CBX_U8
#undef CBX_U12
#undef CBX_U80
#undef CBX_U16
#undef CBX_ETA
#undef CBX_ETA2
#undef CBX_ETA4
#undef CBX_ETA8
#undef CBX_ETA16
#undef CBX_ETA64
#undef CBX_ETA128
#undef CBX_ETA256
#undef CBX_ETA512
#undef CBX_ETA1024
#undef CBX_FMAX
#undef CBX_RT
#undef CBX_R19
#undef CBX_R20
#undef CBX_R21
#undef CBX_RW
#undef CBX_SB
#undef CBX_SR1
#undef CBX_SR2
#undef CBX_STINY
#undef CBX_SUP
#undef CBX_SDN
#undef CBX_SQE
#undef CBX_SA
#undef CBX_EB
#undef CBX_EP
#undef CBX_CLASS_HEAD
#undef CBX_CLASS_TAIL
#undef CBX_INST
