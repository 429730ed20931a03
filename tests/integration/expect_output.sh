#!/usr/bin/env bash
# expect_output.sh EXPECTED_EXIT STREAM PATTERN ABSENT COMMAND...: passes when COMMAND exits with
# EXPECTED_EXIT and its STREAM (stdout, stderr or both) matches the extended regular expression
# PATTERN and, unless ABSENT is "-", does not match ABSENT. For what a command says when it
# succeeds (expect_failure.sh reads stderr only).
expected=$1 stream=$2 pattern=$3 absent=$4
shift 4
case $stream in
  stdout) text=$("$@" 2>/dev/null) ;;
  stderr) text=$("$@" 2>&1 >/dev/null) ;;
  both) text=$("$@" 2>&1) ;;
  *) echo "expect_output.sh: STREAM is stdout, stderr or both, not '$stream'"; exit 1 ;;
esac
status=$?
echo "$text"
if [ "$status" -ne "$expected" ]; then echo "exit status $status, expected $expected"; exit 1; fi
if ! grep -Eq -- "$pattern" <<<"$text"; then echo "$stream does not match: $pattern"; exit 1; fi
if [ "$absent" != - ] && grep -Eq -- "$absent" <<<"$text"; then echo "$stream matches what it must not: $absent"; exit 1; fi
exit 0
