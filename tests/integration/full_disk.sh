#!/usr/bin/env bash
# full_disk.sh OUTDIR LIMIT_KB EXPECT COMMAND...: runs COMMAND (a glossa run into OUTDIR, perhaps
# under mpiexec) where no file may grow past LIMIT_KB kilobytes (ulimit -f: glossa ignores SIGXFSZ,
# so a write past the limit fails with EFBIG, as one on a full disk fails with ENOSPC; MPI's own
# shared-memory files would not fit: PMIx keeps its store in memory and the ranks talk over TCP)
# and passes when
# - the run ends with exit status 4 (not a crash at MPI_Finalize) and says why on stderr;
# - every HDF5 file left reads whole with h5dump, every CSV row has its header's fields and the
#   file ends with a line break, and no temporary (.tmp) file is left;
# - EXPECT=summary: summary.json says the run is over (running false, not converged) and its
#   failure names the file that could not be written;
#   EXPECT=stderr: summary.json itself could not be written: stderr says so, and the summary.json
#   left is the last complete one.
out=$1 limit=$2 expect=$3
shift 3
fail() { echo "$*"; cat "$out.stderr"; exit 1; }
rm -rf "$out" "$out.stdout" "$out.stderr"
mkdir -p "$(dirname "$out")"
(ulimit -f "$limit"; export PMIX_MCA_gds=hash OMPI_MCA_btl=self,tcp; exec "$@") >"$out.stdout" 2>"$out.stderr"
status=$?
cat "$out.stderr"
[ $status -eq 4 ] || fail "exit status $status, expected 4"
grep -Eq "glossa: error: cannot write $out/.*: File too large" "$out.stderr" || fail "stderr does not name the file"
[ -z "$(find "$out" -name '*.tmp')" ] || fail "temporary files left: $(find "$out" -name '*.tmp')"
for h5 in $(find "$out" -name '*.h5'); do h5dump "$h5" >/dev/null 2>&1 || fail "$h5 does not read back"; done
for csv in $(find "$out" -name '*.csv'); do
  [ -z "$(tail -c1 "$csv")" ] || fail "$csv does not end with a line break"
  awk -F, 'NR == 1 { n = NF } NF != n { exit 1 }' "$csv" || fail "$csv has a row cut short"
done
/usr/bin/python3 - "$out" "$expect" "$out.stderr" <<'PY' || exit 1
import json, re, sys
out, expect, stderr = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
summary = json.load(open(out + "/summary.json"))  # complete JSON either way
if expect == "summary":
    failure = summary.get("failure", "")
    ok = summary.get("running") is False and summary.get("converged") is False and \
        re.search(r"could not be written: cannot write " + re.escape(out) + r"/\S+: File too large", failure)
    if not ok: sys.exit("summary.json does not say what happened: running %s, failure %r" % (summary.get("running"), failure))
else:
    if not re.search(r"summary\.json could not be written either", stderr):
        sys.exit("stderr does not say that summary.json could not be written")
    if summary.get("running") is not True: sys.exit("the summary left is not the last complete one")
PY
