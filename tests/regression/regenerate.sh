#!/bin/sh
# Regenerates the stored reference trace of a deck, on purpose only (never called by a test):
#   sh tests/regression/regenerate.sh inputs/paper/s7_1_a_internal.xml [build [NAME [--set path=value ...]]]
# runs the deck on 1 rank and copies its traces.csv to tests/regression/NAME.csv (NAME: the deck's
# name), a scene with airflow's airflow.csv to NAME_flow.csv, one with an airway's airway.csv to
# NAME_lumen.csv and its summary.json's pcrit to NAME_pcrit.json; the --set options are those of
# the test (e.g. a shortened end time).
# Review the difference (git diff) and say why in the commit message.
set -e
deck="$1"
build="${2:-build}"
[ -f "$deck" ] || { echo "usage: $0 DECK.xml [BUILD_DIR [NAME [--set path=value ...]]]" >&2; exit 2; }
name="${3:-$(basename "$deck" .xml)}"
[ $# -ge 3 ] && shift 3 || shift $#
out=$(mktemp -d)
"$build/glossa" run "$deck" --output "$out" --quiet --set Output/fields=false "$@"
cp "$out/traces.csv" "$(dirname "$0")/$name.csv"
echo "wrote $(dirname "$0")/$name.csv"
if [ -f "$out/airflow.csv" ]; then
  cp "$out/airflow.csv" "$(dirname "$0")/${name}_flow.csv"
  echo "wrote $(dirname "$0")/${name}_flow.csv"
fi
if [ -f "$out/airway.csv" ]; then
  cp "$out/airway.csv" "$(dirname "$0")/${name}_lumen.csv"
  echo "wrote $(dirname "$0")/${name}_lumen.csv"
fi
if grep -q '"pcrit"' "$out/summary.json"; then
  python3 -c "import json, sys; json.dump(json.load(open(sys.argv[1]))['pcrit'], open(sys.argv[2], 'w'), indent=2, sort_keys=True)" \
    "$out/summary.json" "$(dirname "$0")/${name}_pcrit.json"
  echo "wrote $(dirname "$0")/${name}_pcrit.json"
fi
