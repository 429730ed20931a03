#!/usr/bin/env bash
# progress_lines.sh GLOSSA DECK OUT: the console of a run as a person reads it (doc/output.md).
# Default: one line per step, "step k/N  t = ... of T s ... [E elapsed, about R left]", and no
# per-iteration lines; --verbose adds every Newton iteration; --quiet prints nothing on stdout.
set -u
glossa=$1 deck=$2 out=$3
fail() { echo "FAIL: $*"; exit 1; }
default=$("$glossa" run "$deck" --output "$out/default" --set Output/fields=false) || fail "default run exited $?"
echo "$default"
steps=$(grep -cE '^step [0-9]+/[0-9]+  t = [0-9.e+-]+ of [0-9.e+-]+ s .*\[[0-9]+ s elapsed, about [0-9]+ s left\]$' <<<"$default")
[ "$steps" -eq 5 ] || fail "expected 5 step lines, found $steps"
grep -qE '^step 5/5  t = 1 of 1 s ' <<<"$default" || fail "the last step is not 'step 5/5  t = 1 of 1 s'"
grep -qE '^step 1/5 ' <<<"$default" || fail "the first step does not count 5 steps"
grep -q 'newton  1  |f|' <<<"$default" && fail "per-iteration lines without --verbose"
verbose=$("$glossa" run "$deck" --output "$out/verbose" --set Output/fields=false --verbose) || fail "verbose run exited $?"
grep -q 'newton  1  |f|' <<<"$verbose" || fail "--verbose shows no Newton iterations"
grep -qE '^step 5/5 ' <<<"$verbose" || fail "--verbose lost the step lines"
quiet=$("$glossa" run "$deck" --output "$out/quiet" --set Output/fields=false --quiet) || fail "quiet run exited $?"
[ -z "$quiet" ] || fail "--quiet printed: $quiet"
echo "ok"
