/*
 * ACSL logic of the binary32 twins of the binary64-only projective bounds
 * (cbx_project_spheref, cbx_project_box_nearf, cbx_project_sphere_nearf;
 * src/f32/cbx_pwide.c): the float inputs' special cases and domain, the
 * tightness they promise, and the lemmas that carry a binary64 end over to
 * the float end rounded outward from it.  Read by Frama-C only (certbox.h
 * includes it once; the predicates on float structures only when the
 * binary32 logic is present as well).
 *
 * A twin widens its float inputs to double (exact), calls the binary64
 * function and rounds each end outward to float (pw_near: at most
 * 2^-22 |end| + 2^-147 away, a float unit or two).  Containment carries over
 * because a wider interval contains more (W > 0 at every point bounded);
 * tightness with twice the binary64 slack, pw_tau(v) = 2^-19 (1 + |v|)
 * (lemmas pw_hi, pw_lo).  The statements about points are those of the
 * binary64 functions (specs/cbx_psph.h, cbx_pnear.h, cbx_pball.h), read on
 * the float values as reals.
 */
#ifndef CBX_PWIDE_H
#define CBX_PWIDE_H


/*@ // ---------------------------------------------------------------------
    // A float end l (h) rounded outward from the binary64 end lo (hi), at
    // most 2^-22 |end| + 2^-147 away; the twins' tightness slack, twice the
    // binary64 one (ps_tau).
    // ---------------------------------------------------------------------
    predicate pw_near(real l, real lo, real h, real hi) =
      l <= lo && lo - (0x1p-22 * \abs(lo) + 0x1p-147) <= l
      && hi <= h && h <= hi + (0x1p-22 * \abs(hi) + 0x1p-147);
    logic real pw_tau(real v) = 0x1p-19 * (1 + \abs(v));

    // The tightness of one output axis of each twin: ps_tight, pn_tight,
    // pb_tight with pw_tau in place of ps_tau.
    predicate psf_tight(real lo, real hi, real a0, real a1, real a2, real a3,
                        real b0, real b1, real b2, real b3, real c0, real c1, real c2, real r) =
      (\exists real s; hi - pw_tau(hi) <= s && ps_above(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r))
      && (\exists real s; s <= lo + pw_tau(lo) && ps_below(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r));
    predicate pnf_tight(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                        real l0, real h0, real l1, real h1, real l2, real h2, real wn) =
      (\exists real s; hi - pw_tau(hi) <= s
         && pn_above(s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn))
      && (\exists real s; s <= lo + pw_tau(lo)
         && pn_below(s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn));
    predicate pbf_tight(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                        real c0, real c1, real c2, real r, real wn) =
      (\exists real s; hi - pw_tau(hi) <= s
         && pb_above(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn))
      && (\exists real s; s <= lo + pw_tau(lo)
         && pb_below(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn));
    predicate pef_tight(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                        real c0, real c1, real c2,
                        real r00, real r01, real r02, real r10, real r11, real r12,
                        real r20, real r21, real r22, real s0, real s1, real s2) =
      (\exists real u; hi - pw_tau(hi) <= u
         && pe_above(u, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2))
      && (\exists real u; u <= lo + pw_tau(lo)
         && pe_below(u, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2));
*/

#if !defined(CBX_FRAMAC_ONLY_64) /* the float structures' logic is there */
/*@ // ---------------------------------------------------------------------
    // Special inputs and the domain, on float inputs: the same conditions
    // as ps_nan, ps_dom, pn_dom, pb_nan, pb_dom of the binary64 functions.
    // ---------------------------------------------------------------------
    predicate pwf_fin(cbx_projf *p) =
         \is_finite(p->m[0][0]) && \is_finite(p->m[0][1]) && \is_finite(p->m[0][2]) && \is_finite(p->m[0][3])
      && \is_finite(p->m[1][0]) && \is_finite(p->m[1][1]) && \is_finite(p->m[1][2]) && \is_finite(p->m[1][3])
      && \is_finite(p->m[2][0]) && \is_finite(p->m[2][1]) && \is_finite(p->m[2][2]) && \is_finite(p->m[2][3])
      && \is_finite(p->m[3][0]) && \is_finite(p->m[3][1]) && \is_finite(p->m[3][2]) && \is_finite(p->m[3][3]);
    predicate pwf_rows(cbx_projf *p) =
         ps_row(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3])
      && ps_row(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3])
      && ps_row(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3])
      && ps_row(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);
    predicate psf_nan(cbx_projf *p, float *c, float r) =
      proj_nan_f(p) || \is_NaN(c[0]) || \is_NaN(c[1]) || \is_NaN(c[2]) || \is_NaN(r);
    // psf_fin, pnf_fin, pef_fin: every input finite and the map's rows in
    // the binary64 functions' range (what each twin's C check of its inputs
    // tests, before it widens them; the ball clipped at a near plane checks
    // psf_fin and its wn)
    predicate psf_fin(cbx_projf *p, float *c, float r) =
      pwf_fin(p) && pwf_rows(p) && \is_finite(c[0]) && \is_finite(c[1]) && \is_finite(c[2]) && \is_finite(r);
    predicate psf_dom(cbx_projf *p, float *c, float r) = psf_fin(p, c, r) && ps_ctr(c[0], c[1], c[2], r);
    predicate pnf_nan(cbx_projf *p, cbx_boxf *b, float wn) =
      proj_nan_f(p) || box_nan_f(b) || \is_NaN(wn);
    predicate pnf_fin(cbx_projf *p, cbx_boxf *b, float wn) =
      pwf_fin(p) && pwf_rows(p) && \is_finite(b->lo[0]) && \is_finite(b->hi[0]) && \is_finite(b->lo[1])
      && \is_finite(b->hi[1]) && \is_finite(b->lo[2]) && \is_finite(b->hi[2]) && \is_finite(wn);
    predicate pnf_dom(cbx_projf *p, cbx_boxf *b, float wn) =
      pnf_fin(p, b, wn) && pn_bx(b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]) && pn_wn(wn);
    predicate pbf_nan(cbx_projf *p, float *c, float r, float wn) = psf_nan(p, c, r) || \is_NaN(wn);
    predicate pbf_dom(cbx_projf *p, float *c, float r, float wn) =
      psf_dom(p, c, r) && \is_finite(wn) && pn_wn(wn);
    predicate pef_nan(cbx_projf *p, float *c, float *s, float (*r)[3]) =
      proj_nan_f(p) || \is_NaN(c[0]) || \is_NaN(c[1]) || \is_NaN(c[2])
      || \is_NaN(s[0]) || \is_NaN(s[1]) || \is_NaN(s[2])
      || \is_NaN(r[0][0]) || \is_NaN(r[0][1]) || \is_NaN(r[0][2]) || \is_NaN(r[1][0]) || \is_NaN(r[1][1])
      || \is_NaN(r[1][2]) || \is_NaN(r[2][0]) || \is_NaN(r[2][1]) || \is_NaN(r[2][2]);
    predicate pef_fin(cbx_projf *p, float *c, float *s, float (*r)[3]) =
      pwf_fin(p) && pwf_rows(p) && \is_finite(c[0]) && \is_finite(c[1]) && \is_finite(c[2])
      && \is_finite(s[0]) && \is_finite(s[1]) && \is_finite(s[2])
      && \is_finite(r[0][0]) && \is_finite(r[0][1]) && \is_finite(r[0][2]) && \is_finite(r[1][0])
      && \is_finite(r[1][1]) && \is_finite(r[1][2]) && \is_finite(r[2][0]) && \is_finite(r[2][1])
      && \is_finite(r[2][2]);
    predicate pef_dom(cbx_projf *p, float *c, float *s, float (*r)[3]) =
      pef_fin(p, c, s, r) && ps_ctr(c[0], c[1], c[2], 0)
      && pe_sh(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2], s[0], s[1], s[2]);

    // A float map (box) widened to double: the same values, all finite.
    predicate pw_wide(cbx_proj *d, cbx_projf *p) =
         d->m[0][0] == p->m[0][0] && d->m[0][1] == p->m[0][1] && d->m[0][2] == p->m[0][2] && d->m[0][3] == p->m[0][3]
      && d->m[1][0] == p->m[1][0] && d->m[1][1] == p->m[1][1] && d->m[1][2] == p->m[1][2] && d->m[1][3] == p->m[1][3]
      && d->m[2][0] == p->m[2][0] && d->m[2][1] == p->m[2][1] && d->m[2][2] == p->m[2][2] && d->m[2][3] == p->m[2][3]
      && d->m[3][0] == p->m[3][0] && d->m[3][1] == p->m[3][1] && d->m[3][2] == p->m[3][2] && d->m[3][3] == p->m[3][3]
      && \is_finite(d->m[0][0]) && \is_finite(d->m[0][1]) && \is_finite(d->m[0][2]) && \is_finite(d->m[0][3])
      && \is_finite(d->m[1][0]) && \is_finite(d->m[1][1]) && \is_finite(d->m[1][2]) && \is_finite(d->m[1][3])
      && \is_finite(d->m[2][0]) && \is_finite(d->m[2][1]) && \is_finite(d->m[2][2]) && \is_finite(d->m[2][3])
      && \is_finite(d->m[3][0]) && \is_finite(d->m[3][1]) && \is_finite(d->m[3][2]) && \is_finite(d->m[3][3]);
    predicate pw_wbox(cbx_box *d, cbx_boxf *b) =
         d->lo[0] == b->lo[0] && d->hi[0] == b->hi[0] && d->lo[1] == b->lo[1] && d->hi[1] == b->hi[1]
      && d->lo[2] == b->lo[2] && d->hi[2] == b->hi[2]
      && \is_finite(d->lo[0]) && \is_finite(d->hi[0]) && \is_finite(d->lo[1]) && \is_finite(d->hi[1])
      && \is_finite(d->lo[2]) && \is_finite(d->hi[2]);
*/
#endif

#ifdef CBX_PWIDE_LEMMAS
/*@ // The outward rounding moves an end by less than the slack it adds:
    // |h - hi| <= 2^-22 |hi| + 2^-147 <= pw_tau(h) - ps_tau(hi).
    lemma pw_hi: \forall real h, hi; hi <= h <= hi + (0x1p-22 * \abs(hi) + 0x1p-147)
      ==> h - pw_tau(h) <= hi - ps_tau(hi);
    lemma pw_lo: \forall real l, lo; lo - (0x1p-22 * \abs(lo) + 0x1p-147) <= l <= lo
      ==> lo + ps_tau(lo) <= l + pw_tau(l);

    // A wider interval bounds as much: W > 0 at every point bounded (the
    // ball: ps_xw; the clipped parts: W >= wn > 0), so l <= lo gives
    // l W <= lo W <= X, and hi <= h gives X <= hi W <= h W.
    // One point, one side: with W > 0 there, l <= lo gives l W <= lo W
    // (the named product fact pw_mono).
    predicate pw_mono(real l, real lo, real w) = l * w <= lo * w;
    lemma pw_mono_at: \forall real l, lo, w; l <= lo && 0 < w ==> pw_mono(l, lo, w);
    lemma ps_pt_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      ps_xw(b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      && ps_xlo(lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      && ps_xhi(hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2) && l <= lo && hi <= h
      && pw_mono(l, lo, aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2))
      && pw_mono(hi, h, aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2))
      ==> ps_xlo(l, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
          && ps_xhi(h, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    lemma pn_pt_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2;
      pn_xlo(lo, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2)
      && pn_xhi(hi, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2) && l <= lo && hi <= h
      && pw_mono(l, lo, aff(b0, b1, b2, b3, x0, x1, x2)) && pw_mono(hi, h, aff(b0, b1, b2, b3, x0, x1, x2))
      ==> pn_xlo(l, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2)
          && pn_xhi(h, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2);
    lemma pe_pt_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2;
      pe_at(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2) && l <= lo && hi <= h
      && pw_mono(l, lo, aff(b0, b1, b2, b3, x0, x1, x2)) && pw_mono(hi, h, aff(b0, b1, b2, b3, x0, x1, x2))
      ==> pe_at(l, h, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2);
    lemma pe_axis_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                             r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2;
      pe_axis(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      && l <= lo && hi <= h
      ==> pe_axis(l, h, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    lemma ps_axis_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r;
      ps_axis(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r) && l <= lo && hi <= h
      ==> ps_axis(l, h, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    lemma pn_axis_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn;
      pn_axis(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn) && l <= lo && hi <= h
      && 0 < wn
      ==> pn_axis(l, h, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    lemma pb_axis_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn;
      pb_axis(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn) && l <= lo && hi <= h
      && 0 < wn
      ==> pb_axis(l, h, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);

    // The binary64 tightness, carried to the float ends (pw_hi, pw_lo).
    lemma ps_tight_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r;
      ps_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r) && pw_near(l, lo, h, hi)
      ==> psf_tight(l, h, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    lemma pn_tight_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn;
      pn_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn) && pw_near(l, lo, h, hi)
      ==> pnf_tight(l, h, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    lemma pe_tight_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                              r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2;
      pe_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      && pw_near(l, lo, h, hi)
      ==> pef_tight(l, h, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    lemma pb_tight_w: \forall real l, h, lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn;
      pb_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn) && pw_near(l, lo, h, hi)
      ==> pbf_tight(l, h, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
*/
#endif /* CBX_PWIDE_LEMMAS */

#endif /* CBX_PWIDE_H */
