(* certbox: what a prover task does not need, left out by Why3
   transformations (compiled and loaded into Frama-C with proofs/idle.ml by
   proofs/plugin.sh; named in the drivers that proofs/setup.sh writes):
   first certbox_prune64 / _prune32 / _prunew, the axioms no goal of a
   family needs (this comment); second certbox_strip, the float facts a
   memory-access goal does not need; last certbox_relevant /
   _relevant_wp, the axioms a goal cannot use (both below).

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

(* the declarations of a theory as loaded *)
let decls env path th = (Env.read_theory env path th).Theory.th_decls

(* the prop symbols named by a list, looked up in the theories as loaded *)
let props env spec =
  List.fold_left
    (fun acc (path, th, names) ->
      List.fold_left
        (fun acc td ->
          match td.Theory.td_node with
          | Theory.Decl { Decl.d_node = Decl.Dprop ((Decl.Paxiom | Decl.Plemma), pr, _) }
            when names = [] || List.mem pr.Decl.pr_name.Ident.id_string names ->
              Decl.Spr.add pr acc
          | _ -> acc)
        acc (decls env path th))
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

(* certbox_strip: a memory-access goal without the float facts.
   Most goals that -wp-rte adds are memory accesses: \valid_read(a + 3),
   \valid(out + i), \separated(...) (1,665 of the prover tasks, 2026-11-30).
   Their proof needs the functions' validity and separation preconditions
   and integer arithmetic, never a fact about a float; yet each task carries
   every float hypothesis of its path and the whole IEEE theory, which CVC4
   preprocesses (about 0.14 s a task) before it looks at the goal.  For a
   task whose goal, once its premises are moved into hypotheses (Why3's
   introduce_premises), is a conjunction of WP's memory predicates
   (valid_rd, valid_rw, valid_obj, invalid, separated, included), this
   leaves out every declaration that names a float: the IEEE types (binary64,
   binary32, the rounding modes), then in order every symbol whose type or
   definition names one of those, every axiom and hypothesis that names one,
   and the metas about them.  Every other task goes on unchanged.
   Like certbox_prune*, it only takes hypotheses away (a declaration is left
   out only with everything that names it, so the task stays well formed;
   if the goal itself names a symbol left out, the task goes on unchanged):
   a goal proved from fewer hypotheses is proved from all of them. *)

(* the types of the IEEE theories: binary64, binary32, rounding modes *)
let float_types env =
  List.fold_left
    (fun acc th ->
      List.fold_left
        (fun acc td ->
          match td.Theory.td_node with
          | Theory.Decl { Decl.d_node = Decl.Dtype ts } -> Ty.Sts.add ts acc
          | _ -> acc)
        acc (decls env [ "ieee_float" ] th))
    Ty.Sts.empty [ "Float64"; "Float32"; "RoundingMode" ]

(* WP's memory predicates (frama_c_wp/memory.mlw) *)
let mem_preds env =
  let th = Env.read_theory env [ "frama_c_wp"; "memory" ] "Memory" in
  List.fold_left
    (fun acc n -> Term.Sls.add (Theory.ns_find_ls th.Theory.th_export [ n ]) acc)
    Term.Sls.empty
    [ "valid_rw"; "valid_rd"; "valid_obj"; "invalid"; "separated"; "included" ]

(* what is left out so far: types, function and predicate symbols, props *)
type gone = { tys : Ty.Sts.t; lss : Term.Sls.t; prs : Decl.Spr.t }

let names_gone g =
  let ty t = Ty.ty_s_any (fun ts -> Ty.Sts.mem ts g.tys) t in
  let tm t = Term.t_s_any ty (fun ls -> Term.Sls.mem ls g.lss) t in
  let sg ls = List.exists ty ls.Term.ls_args || Opt.fold (fun _ -> ty) false ls.Term.ls_value in
  let open Decl in
  function
  | Dtype ts -> (match ts.Ty.ts_def with Ty.Alias t -> ty t | _ -> false)
  | Ddata dl -> List.exists (fun (_, cl) -> List.exists (fun (cs, _) -> sg cs) cl) dl
  | Dparam ls -> sg ls
  | Dlogic l -> List.exists (fun (ls, ld) -> sg ls || tm (ls_defn_axiom ld)) l
  | Dind (_, l) -> List.exists (fun (ls, ax) -> sg ls || List.exists (fun (_, f) -> tm f) ax) l
  | Dprop (_, _, f) -> tm f

let leave_out g d =
  let ls g l = { g with lss = Term.Sls.add l g.lss } in
  let open Decl in
  match d.d_node with
  | Dtype ts -> { g with tys = Ty.Sts.add ts g.tys }
  | Ddata dl ->
      List.fold_left
        (fun g (ts, cl) ->
          List.fold_left
            (fun g (cs, pl) -> List.fold_left (fun g p -> Opt.fold ls g p) (ls g cs) pl)
            { g with tys = Ty.Sts.add ts g.tys } cl)
        g dl
  | Dparam l -> ls g l
  | Dlogic l -> List.fold_left (fun g (l, _) -> ls g l) g l
  | Dind (_, l) -> List.fold_left (fun g (l, _) -> ls g l) g l
  | Dprop (_, pr, _) -> { g with prs = Decl.Spr.add pr g.prs }

let meta_gone g =
  List.exists (function
    | Theory.MAty t -> Ty.ty_s_any (fun ts -> Ty.Sts.mem ts g.tys) t
    | Theory.MAts ts -> Ty.Sts.mem ts g.tys
    | Theory.MAls l -> Term.Sls.mem l g.lss
    | Theory.MApr pr -> Decl.Spr.mem pr g.prs
    | _ -> false)

exception Goal_gone

let strip env =
  let mems = mem_preds env in
  let rec memory c =
    match c.Term.t_node with
    | Term.Tapp (ls, _) -> Term.Sls.mem ls mems
    | Term.Tbinop (Term.Tand, a, b) -> memory a && memory b
    | _ -> false
  in
  let intro = Trans.lookup_transform "introduce_premises" env in
  (* one pass over the declarations, memoised on the task's prefix like
     Why3's own transformations: the library's theories, which every task
     shares, are looked at once *)
  let cut =
    Trans.fold_map
      (fun hd (g, task) ->
        let td = hd.Task.task_decl in
        match td.Theory.td_node with
        | Theory.Decl { Decl.d_node = Decl.Dprop (Decl.Pgoal, _, _) as d } ->
            if names_gone g d then raise Goal_gone else (g, Task.add_tdecl task td)
        | Theory.Decl d ->
            if names_gone g d.Decl.d_node then (leave_out g d, task) else (g, Task.add_tdecl task td)
        | Theory.Meta (_, args) -> if meta_gone g args then (g, task) else (g, Task.add_tdecl task td)
        | _ -> (g, Task.add_tdecl task td))
      { tys = float_types env; lss = Term.Sls.empty; prs = Decl.Spr.empty }
      None
  in
  Trans.store (fun task ->
      let t = Trans.apply intro task in
      if not (memory (Task.task_goal_fmla t)) then task
      else try Trans.apply cut t with Goal_gone -> task)

let () =
  Trans.register_env_transform "certbox_strip" strip
    ~desc:"certbox: a memory-access goal without the declarations that name a float (proofs/prune.ml)"

(* certbox_relevant: a task without the axioms its goal cannot use.
   Named last in the drivers, after Why3 has turned each definition into a
   declaration and its axiom (f'def).  From the symbols of the goal (WP's
   hypotheses are part of it), an axiom is kept when it names none of the
   symbols that carry relevance (the IEEE and conversion operations of the
   list below: add, mul, to_f64, ...; WP's own predicates and functions,
   P_ and L_), or one of those that occurs in the task kept so far; a
   definition's axiom (f'def) is kept when f occurs, or carries none; each
   kept axiom adds its symbols, until nothing changes (SInE's idea, with
   those symbols as triggers).  certbox_relevant_wp, for the unit with
   both families' logic (proofs/pwide.c), takes only WP's symbols as
   triggers and keeps every IEEE axiom: with the operations as triggers
   too, the assertion eq of cbx_project_box_nearf (the hardest goal there,
   22 s of CVC4 with every axiom) was not proved in 100 s; with the IEEE
   axioms kept, in 16 s.  A smoke job (CBX_WP_WHOLE_TASKS set)
   keeps every hypothesis: it asks whether they are consistent.  Every
   declaration of a type or a symbol stays, so the task stays well formed;
   only axioms go.
   Measured on the prover tasks of jobs K64, T64, B64a (1,284 tasks, all
   proved either way by CVC4 alone) with a first, stricter rule (every
   operation an axiom names had to occur already; it left out a bridge
   that a loop invariant needed, and gave way to the rule above): the
   tasks a third to half smaller, CVC4 time 15 to 29% less.  With the rule
   above, the whole proof run (make proof-check, clean clone, 2 cores)
   took 1,176 s instead of 1,430 s.  Like certbox_prune*, it only takes
   hypotheses away: a goal proved from fewer hypotheses is proved from all
   of them. *)

let ops =
  [ "add"; "sub"; "mul"; "div"; "neg"; "abs"; "fma"; "sqrt"; "roundToIntegral"; "min"; "max";
    "of_int"; "to_int"; "to_f32"; "to_f64"; "to_float32"; "to_float64"; "round_float";
    "round_double" ]

let wp_symbol (ls : Term.lsymbol) =
  let s = ls.Term.ls_name.Ident.id_string in
  String.length s > 2 && (String.sub s 0 2 = "P_" || String.sub s 0 2 = "L_")

(* the function and predicate symbols a formula names, memoised per
   declaration (declarations are shared by the tasks of a run) *)
let syms_memo : Term.Sls.t Decl.Hdecl.t = Decl.Hdecl.create 4096

let decl_syms d f =
  match Decl.Hdecl.find_opt syms_memo d with
  | Some s -> s
  | None ->
      let s = Term.t_s_fold (fun acc _ -> acc) (fun acc ls -> Term.Sls.add ls acc) Term.Sls.empty f in
      Decl.Hdecl.add syms_memo d s;
      s

(* a smoke job keeps every hypothesis: it asks whether they are consistent
   (proofs/job.sh and scripts/smoke_teeth.sh set CBX_WP_WHOLE_TASKS; WP's
   smoke goal is not a recognisable "false": Qed moves the last hypothesis
   into the conclusion) *)
let whole = Sys.getenv_opt "CBX_WP_WHOLE_TASKS" <> None

let relevant ~ieee task =
  match task with
  | None -> task
  | Some _ when whole -> task
  | Some _ ->
      let tds = Task.task_tdecls task in
      (* the axioms, each with its symbols and the symbol it defines: a
         definition's axiom is named after its symbol (f'def, Why3's
         eliminate_definition), declared before it, not always just
         before (the polymorphism encoding puts its bridges between) *)
      let declared = Hashtbl.create 256 in
      let axioms = ref [] and goal = ref Term.Sls.empty in
      List.iter
        (fun td ->
          match td.Theory.td_node with
          | Theory.Decl { Decl.d_node = Decl.Dparam ls } ->
              Hashtbl.replace declared ls.Term.ls_name.Ident.id_string ls
          | Theory.Decl ({ Decl.d_node = Decl.Dprop (Decl.Pgoal, _, f) } as d) -> goal := decl_syms d f
          | Theory.Decl ({ Decl.d_node = Decl.Dprop ((Decl.Paxiom | Decl.Plemma), pr, f) } as d) ->
              let n = pr.Decl.pr_name.Ident.id_string in
              let k = String.length n - 4 in
              let def =
                if k > 0 && String.sub n k 4 = "'def" then Hashtbl.find_opt declared (String.sub n 0 k)
                else None
              in
              axioms := (pr, def, decl_syms d f) :: !axioms
          | _ -> ())
        tds;
      (* the symbols that make an axiom relevant: the operations, and WP's
         own symbols (P_, L_) *)
      let carries ls = (ieee && List.mem ls.Term.ls_name.Ident.id_string ops) || wp_symbol ls in
      let keep = ref Decl.Spr.empty and s = ref !goal and changed = ref true in
      let axioms = List.rev !axioms in
      (* each round looks only at the axioms not kept yet, in the task's
         order, each with its carrying symbols computed once *)
      let pending = ref (List.map (fun (pr, def, syms) -> (pr, def, syms, Term.Sls.filter carries syms)) axioms) in
      while !changed do
        changed := false;
        pending :=
          List.filter
            (fun (pr, def, syms, r) ->
              let ok =
                match def with
                | Some ls -> Term.Sls.mem ls !s || not (carries ls)
                | None -> Term.Sls.is_empty r || Term.Sls.exists (fun ls -> Term.Sls.mem ls !s) r
              in
              if ok then begin
                keep := Decl.Spr.add pr !keep;
                s := Term.Sls.union syms !s;
                changed := true
              end;
              not ok)
            !pending
      done;
      let gone =
        List.fold_left
          (fun g (pr, _, _) -> if Decl.Spr.mem pr !keep then g else Decl.Spr.add pr g)
          Decl.Spr.empty axioms
      in
      if Decl.Spr.is_empty gone then task
      else
        List.fold_left
          (fun t td ->
            match td.Theory.td_node with
            | Theory.Decl { Decl.d_node = Decl.Dprop ((Decl.Paxiom | Decl.Plemma), pr, _) }
              when Decl.Spr.mem pr gone -> t
            | Theory.Meta (_, args)
              when meta_gone { tys = Ty.Sts.empty; lss = Term.Sls.empty; prs = gone } args -> t
            | _ -> Task.add_tdecl t td)
          None tds

let () =
  Trans.register_transform "certbox_relevant" (Trans.store (relevant ~ieee:true))
    ~desc:"certbox: leave out the axioms the goal cannot use (proofs/prune.ml)";
  Trans.register_transform "certbox_relevant_wp" (Trans.store (relevant ~ieee:false))
    ~desc:"certbox: leave out the axioms of WP's symbols the goal cannot use (proofs/prune.ml)"
