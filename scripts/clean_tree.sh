#!/bin/sh
# make check leaves the checkout as it found it: a clean clone stays clean
# (generated files go to build/, which git ignores).
#   sh scripts/clean_tree.sh save FILE    record the checkout's state (first
#                                         step of make check)
#   sh scripts/clean_tree.sh check FILE   its last step: fails when
#                                         `git status --porcelain` is not
#                                         empty, or, in a checkout that had
#                                         local changes before the run, when
#                                         the run changed them
# The state: `git status --porcelain` (untracked files included, ignored ones
# not) and a digest of the changes to tracked files and of the untracked
# files.  Outside a git work tree (an unpacked release) there is nothing to
# check: both say so and succeed.  Run from the checkout's root.
set -eu
what=${1:-}; file=${2:-}
case $what in save|check) [ -n "$file" ] ;; *) false ;; esac || {
  echo "usage: $0 save|check FILE" >&2; exit 2; }
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "clean-tree: not a git work tree: nothing to check"
  exit 0
fi
state() {
  git status --porcelain
  echo "diff $(git diff HEAD --binary | sha256sum | cut -c1-64)"
  echo "new $(git ls-files -z -o --exclude-standard | LC_ALL=C sort -z | xargs -0r sha256sum | sha256sum | cut -c1-64)"
}
if [ "$what" = save ]; then
  mkdir -p "$(dirname "$file")"
  state > "$file"
  n=$(git status --porcelain | wc -l)
  [ "$n" = 0 ] && echo "clean-tree: the checkout is clean" \
    || echo "clean-tree: note: $n local changes before the run (git status); the last step checks that the run adds none"
  exit 0
fi
now=$(git status --porcelain)
if [ -z "$now" ]; then
  echo "clean-tree: ok: git status shows nothing"
  exit 0
fi
if [ -f "$file" ] && [ -n "$(sed '/^diff /d; /^new /d' "$file")" ] && [ "$(state)" = "$(cat "$file")" ]; then
  echo "clean-tree: ok: the run changed nothing (the $(echo "$now" | wc -l) local changes of git status were there before it)"
  exit 0
fi
echo "$now"
echo "clean-tree: FAILED: the checkout is not as the run found it (git status above; generated files belong in build/)"
exit 1
