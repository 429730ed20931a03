#!/usr/bin/env bash
# expect_failure.sh EXPECTED_EXIT PATTERN COMMAND...: passes when COMMAND exits with
# EXPECTED_EXIT and its standard error matches the extended regular expression PATTERN.
expected=$1 pattern=$2
shift 2
err=$("$@" 2>&1 >/dev/null)
status=$?
echo "$err"
if [ "$status" -ne "$expected" ]; then echo "exit status $status, expected $expected"; exit 1; fi
if ! grep -Eq -- "$pattern" <<<"$err"; then echo "message does not match: $pattern"; exit 1; fi
