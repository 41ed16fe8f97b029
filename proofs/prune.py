"""Prover front end of the regular proof passes (proofs/setup.sh: the
cvc4p and z3p entries): drop from one SMT-LIB task the hypotheses that
name none of the goal's own logic, then run the prover on what is left.

  python3 -S proofs/prune.py PROVER ARGS... FILE

WP puts every lemma of the translation unit into every goal's context
(ACSL lemmas outside an axiomatic block are global), and each lemma brings
the definitions it mentions: a goal of cbx_project_sphere carried the
class lemmas, the interval-matrix lemmas, the chain lemmas and some sixty
definitions it never uses, about half of its 125 kB.  This filter keeps

  - every block that is not the project's logic: the prelude, the
    theories of Why3 and WP (reals, IEEE floats, memory), the goal itself;
  - the definitions of the project's predicates and logic functions
    (Why3 names P_..., L_...) that the kept blocks mention, transitively;
  - every lemma (Q_...) that mentions one of those symbols, or none of the
    project's symbols at all (a fact about the reals alone), with the
    definitions it mentions in turn.

It only deletes: what it writes is a subsequence of the task's commands, in
their order (the sort and datatype declarations of a deleted block are kept
so that the rest still parses).  A set of assertions that is unsatisfiable
stays so with more assertions, so a goal the prover proves here is proved
with the whole context; a goal that needed a deleted lemma fails here and is
proved again with the whole context by pass 2 (proofs/job.sh).  If anything
here fails, the task is left as it was.  The smoke tests never use it (they
ask whether the whole context is consistent).

Measured 2026-11-29 on 158 tasks of proofs/psph.c and proofs/all.c (CVC4
1.8): tasks 160 kB -> 121 kB on average, the prover's CPU time on the
146 routine ones 107 s -> 61 s, every task proved before proved after.
"""
import os
import re
import sys

USER = ('P_', 'L_', 'Q_')
TOK = re.compile(r"[A-Za-z_][A-Za-z0-9_'.!@$%^&*+<>=/?~-]*")
DECL = re.compile(r'\((?:declare-fun|define-fun|define-fun-rec|declare-const)\s+([^\s()]+)')
KEEP_FORMS = ('(declare-sort', '(declare-datatype')


def forms(text):
    """The top-level forms of text (with the text between them)."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text[i] == '(':
            d, j = 0, i
            while True:
                c = text[j]
                if c == '(':
                    d += 1
                elif c == ')':
                    d -= 1
                    if d == 0:
                        break
                elif c in '|"':
                    j = text.index(c, j + 1)
                elif c == ';':
                    j = text.index('\n', j)
                j += 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            j = text.find('(', i)
            j = n if j < 0 else j
            out.append(text[i:j])
            i = j
    return out


def prune(src):
    # Why3's SMT-LIB printer heads each declaration with ';; NAME'
    blocks = re.split(r'(?m)^(?=;; )', src)
    name = [b.split(None, 2)[1] if b.startswith(';; ') and len(b.split(None, 2)) > 1 else ''
            for b in blocks]
    user = [n.startswith(USER) for n in name]
    lemma = [n.startswith('Q_') for n in name]
    # the symbols of the project's logic -> the blocks that declare or
    # define them (P_x, P_x'def, ...: grouped by the name before ')
    group = {}
    for i, n in enumerate(name):
        if user[i] and not lemma[i]:
            group.setdefault(n.split("'")[0], set()).add(i)
    defs = {}
    for i, b in enumerate(blocks):
        if user[i] and not lemma[i]:
            g = group[name[i].split("'")[0]]
            for s in DECL.findall(b):
                defs.setdefault(s, set()).update(g)
    toks = [set(TOK.findall(b)) for b in blocks]
    keep = [not u for u in user]

    def close(seed):
        todo = list(seed)
        while todo:
            for t in toks[todo.pop()]:
                for j in defs.get(t, ()):
                    if not keep[j]:
                        keep[j] = True
                        todo.append(j)

    close([i for i, k in enumerate(keep) if k])
    reach = set()
    for i, k in enumerate(keep):
        if k:
            reach |= toks[i] & defs.keys()
    picked = []
    for i in range(len(blocks)):
        if lemma[i]:
            syms = toks[i] & defs.keys()
            if not syms or syms & reach:
                keep[i] = True
                picked.append(i)
    close(picked)
    out = []
    for i, b in enumerate(blocks):
        if keep[i]:
            out.append(b)
        elif any(k in b for k in KEEP_FORMS):
            out.extend(f for f in forms(b) if f.startswith(KEEP_FORMS))
    return ''.join(out)


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.stderr.write('usage: prune.py PROVER ARGS... FILE\n')
        return 2
    task = args[-1]
    try:
        with open(task, encoding='utf-8') as f:
            src = f.read()
        small = prune(src)
        with open(task + '.tmp', 'w', encoding='utf-8') as f:
            f.write(small)
        os.replace(task + '.tmp', task)
    except (OSError, ValueError, IndexError, KeyError):
        pass        # the whole task goes to the prover
    os.execv(args[0], args)
    return 2


if __name__ == '__main__':
    sys.exit(main())
