/* Reproducer (see proofs/README.md, "How the batch proof is split"): with
 * the six fields of out[j] as separate arguments of the invariant's
 * predicate, its preservation times out with CVC4 1.8 and Z3 4.8.12 here;
 * src/algo/cbx_batch.c passes out[j] as one struct value instead.
 *   WHY3CONFIG=build/proof/why3.conf frama-c -wp -wp-rte -wp-prover cvc4r,z3r proofs/repro/batch_frame.c */
typedef struct B { double lo[3], hi[3]; } B;
/*@ axiomatic A { predicate P(real x, real y, real z, real u, real v, real w); } */
/*@ requires \valid(o); assigns *o; ensures P(o->lo[0], o->hi[0], o->lo[1], o->hi[1], o->lo[2], o->hi[2]); */
void put(B *o);
/*@ requires \valid(out + (0 .. n-1));
    assigns out[0 .. n-1];
    ensures \forall integer j; 0 <= j < n ==> P(out[j].lo[0], out[j].hi[0], out[j].lo[1], out[j].hi[1], out[j].lo[2], out[j].hi[2]); */
void f(B *out, unsigned long n) {
  unsigned long k;
  /*@ loop invariant 0 <= k <= n;
      loop invariant \forall integer j; 0 <= j < k ==> P(out[j].lo[0], out[j].hi[0], out[j].lo[1], out[j].hi[1], out[j].lo[2], out[j].hi[2]);
      loop assigns k, out[0 .. n-1]; */
  for (k = 0; k < n; k++) {
    B r;
    put(&r);
    out[k].lo[0] = r.lo[0]; out[k].hi[0] = r.hi[0]; out[k].lo[1] = r.lo[1];
    out[k].hi[1] = r.hi[1]; out[k].lo[2] = r.lo[2]; out[k].hi[2] = r.hi[2];
  }
}
