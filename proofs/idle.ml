(* certbox: Frama-C's task loop without its 50 ms naps (compiled and loaded
   by proofs/plugin.sh, with proofs/prune.ml).
   WP runs its goals as tasks of Frama-C's task server (Task in Frama-C's
   kernel): each round of the server's loop moves every running goal one
   step (simplification, the prover's start, a look at whether it has
   finished), and between rounds the default loop sleeps 50 ms.  A goal
   takes a round or more, so a job of a thousand goals slept minutes while
   the cores were idle (measured 2026-11-30, proofs/job.sh K64 alone: 110 s
   with the default loop, 60 s with this one, 70 s with 10 ms naps; the CPU
   time, 96 s, the same in all three).  This loop sleeps 1 ms.  It changes
   when WP looks at its tasks, not what a task does: the goals, the provers,
   their limits and their verdicts are the same.  Where every core is busy
   anyway (proofs/run.sh's pool of three jobs on two cores) it gains little:
   it matters for a job alone, the pool's last jobs and focused runs. *)
let () =
  Task.on_idle :=
    (fun f -> try while f () do Unix.sleepf 0.001 done with Db.Cancel -> ())
