(* certbox: the axioms no goal of a family needs, left out of each prover
   task by one Why3 transformation (compiled and loaded into Frama-C with
   proofs/idle.ml by proofs/plugin.sh; named first in the drivers that
   proofs/setup.sh writes).

   Left out, every axiom (and lemma, which a task carries as an axiom) of:
   - bv.Pow2int, int.Power: the facts about integer powers of two
     (pow2_0 ... pow2_64; ieee_float imports them for its own definitions;
     no specification or code here uses pow2);
   - int.ComputerDivision and five division lemmas of WP's Qed theory: no
     proven function divides integers, no specification uses / or % on
     integers;
   - the IEEE axioms of the operations the proven code never performs: fma,
     division, square root (the code's sqrt and fma are trusted contracts,
     not IEEE operations of the model), rounding to integral values, the
     RNA rounding mode (WP's model rounds to nearest even);
   - in each family's tasks, the other format's IEEE theory (the binary64
     sources use no float, the binary32 sources no double); the unit that
     holds both families' logic (proofs/pwide.c) keeps both.
   Removing an axiom only removes a hypothesis: a goal proved without it is
   proved with it (proofs/README.md, trusted base).

   Until 2026-11-30 the drivers said the same with Why3's `remove prop` and
   `remove allprops` lines.  Each of those adds a meta to every task, and
   each of the driver's later transformations, which rebuilds the task,
   re-adds every meta (hash-consed sets compared and hashed whole):
   a quarter of Frama-C's time.  This transformation drops the same
   declarations with no meta, first, in one pass over the task; the
   prover inputs are byte for byte the same (job K64's 333 tasks:
   identical files; Frama-C's CPU time 37 s instead of 51 s). *)
open Why3

let unused_ops =
  [ "div_finite"; "div_finite_rev"; "div_finite_rev_n"; "div_special";
    "fma_finite"; "fma_finite_rev"; "fma_finite_rev_n"; "fma_special"; "fma_int";
    "sqrt_finite"; "sqrt_finite_rev"; "sqrt_special";
    "roundToIntegral_is_int"; "roundToIntegral_is_finite";
    "truncate_int"; "truncate_neg"; "truncate_pos";
    "ceil_le"; "ceil_lest"; "ceil_to_real"; "ceil_to_int";
    "floor_le"; "floor_lest"; "floor_to_real"; "floor_to_int";
    "RNA_down"; "RNA_up"; "RNA_down_tie"; "RNA_up_tie" ]

let unused_qed =
  [ "c_euclidian"; "cmod_remainder"; "cdiv_neutral"; "cdiv_inv"; "cdiv_closed_remainder" ]

(* (library path, theory, the props left out: [] for every one) *)
let common =
  [ ([ "bv" ], "Pow2int", []); ([ "int" ], "ComputerDivision", []); ([ "int" ], "Power", []);
    ([ "frama_c_wp"; "qed" ], "Qed", unused_qed) ]

let family = function
  | `F64 -> common @ [ ([ "ieee_float" ], "Float64", unused_ops); ([ "ieee_float" ], "Float32", []) ]
  | `F32 -> common @ [ ([ "ieee_float" ], "Float32", unused_ops); ([ "ieee_float" ], "Float64", []) ]
  | `Both -> common @ [ ([ "ieee_float" ], "Float64", unused_ops); ([ "ieee_float" ], "Float32", unused_ops) ]

(* the prop symbols named by a list, looked up in the theories as loaded *)
let props env spec =
  List.fold_left
    (fun acc (path, th, names) ->
      let t = Env.read_theory env path th in
      List.fold_left
        (fun acc td ->
          match td.Theory.td_node with
          | Theory.Decl { Decl.d_node = Decl.Dprop ((Decl.Paxiom | Decl.Plemma), pr, _) }
            when names = [] || List.mem pr.Decl.pr_name.Ident.id_string names ->
              Decl.Spr.add pr acc
          | _ -> acc)
        acc t.Theory.th_decls)
    Decl.Spr.empty spec

let prune fam env =
  let drop = props env (family fam) in
  Trans.decl
    (fun d ->
      match d.Decl.d_node with
      | Decl.Dprop (Decl.Paxiom, pr, _) when Decl.Spr.mem pr drop -> []
      | _ -> [ d ])
    None

let () =
  List.iter
    (fun (name, fam) ->
      Trans.register_env_transform name (prune fam)
        ~desc:"certbox: leave out the axioms no goal of this family needs (proofs/prune.ml)")
    [ ("certbox_prune64", `F64); ("certbox_prune32", `F32); ("certbox_prunew", `Both) ]
