#!/usr/bin/env bash
# Reference runs of deal.II tutorial step-44 (Q1-DGPM0-DGPM0 three-field
# formulation) for verifying Glossa.  deal.II code is NOT part of this repo:
# the tutorial is copied from the Debian package libdeal.ii-doc into a scratch
# directory, patched there, built and run.
#
# Usage: bench/step44_dealii/run_step44.sh [scratch_dir]
# Environment:
#   LEVELS        global refinement levels to run (default "2 3 4"; 5 = 32^3)
#   STATIC_COND   "Use static condensation" for the main runs (default false,
#                 as shipped)
#   SC_COMPARE    levels re-run with the other static-condensation setting to
#                 check the displacement is identical (default "2 3"; "" = off)
#   NICE          nice level (default 10); DEAL_II_NUM_THREADS is forced to 1.
#   PREPARE_ONLY  1 = build (or keep an up-to-date build) and write the parameter
#                 file of each level in LEVELS into its run directory, then stop:
#                 nothing is run and bench/results/ is not touched.  Prints
#                 "STEP44_EXE <executable>" and "STEP44_RUN_DIR <level> <dir>"
#                 (used by bench/step44_vs_dealii.py --dealii run, which times
#                 the executable itself).
# The patched sources replace those in <scratch>/src only where they differ, so
# a second call with the same scratch directory does not rebuild step-44.
# Requires: apt-get install -y libdeal.ii-dev libdeal.ii-doc (Debian 12, deal.II 9.4)
set -euo pipefail

SRC_DIR=/usr/share/doc/libdeal.ii-doc/examples/step-44
REPO_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
RESULTS_DIR="$REPO_DIR/bench/results"
LEVELS="${LEVELS:-2 3 4}"
STATIC_COND="${STATIC_COND:-false}"
SC_COMPARE="${SC_COMPARE-2 3}"
NICE="${NICE:-10}"
PREPARE_ONLY="${PREPARE_ONLY:-}"

SCRATCH="${1:-$(mktemp -d /tmp/step44_dealii.XXXXXX)}"
mkdir -p "$SCRATCH"
SCRATCH="$(cd "$SCRATCH" && pwd)"
echo "scratch directory: $SCRATCH"

for f in step-44.cc parameters.prm CMakeLists.txt; do
  [[ -f "$SRC_DIR/$f" ]] || { echo "missing $SRC_DIR/$f (install libdeal.ii-doc)" >&2; exit 1; }
done

# ---------------------------------------------------------------- copy + patch
# The copy is patched in a staging directory; files identical to those of an
# earlier call are left alone (mtime kept), so make has nothing to rebuild.
SRC="$SCRATCH/src"
STAGE="$SCRATCH/src.new"
rm -rf "$STAGE"; mkdir -p "$STAGE" "$SRC"
cp "$SRC_DIR/step-44.cc" "$SRC_DIR/parameters.prm" "$SRC_DIR/CMakeLists.txt" "$STAGE/"

# Trace block inserted right after `solution_n += solution_delta;` in
# Solid<dim>::run(), i.e. after every converged load step.  The y-displacement
# at the vertex (0,1,0)*scale is read twice: via VectorTools::point_value and
# directly from the vertex DoF (loop over cell vertices); both are printed.
cat > "$STAGE/trace_block.inc" <<'CPP'
        {
          // ---- Glossa verification trace (added by run_step44.sh) ----
          Point<dim> p_top;
          p_top[1] = 1.0 * parameters.scale;
          Vector<double> vals(n_components);
          VectorTools::point_value(dof_handler, solution_n, p_top, vals);
          double uy_vertex = std::numeric_limits<double>::quiet_NaN();
          Point<dim> found_vertex;
          std::vector<types::global_dof_index> ldi(dofs_per_cell);
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              cell->get_dof_indices(ldi);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  if (i >= fe.n_dofs_per_vertex() * GeometryInfo<dim>::vertices_per_cell)
                    break;
                  const unsigned int v = i / fe.n_dofs_per_vertex();
                  if (fe.system_to_component_index(i).first == 1 &&
                      cell->vertex(v).distance(p_top) < 1e-9 * parameters.scale)
                    {
                      uy_vertex    = solution_n(ldi[i]);
                      found_vertex = cell->vertex(v);
                    }
                }
            }
          const unsigned int eps = static_cast<unsigned int>(
            std::lround(std::cbrt(double(triangulation.n_active_cells()))));
          std::ostringstream tr;
          tr << std::setprecision(17) << "STEP44_TRACE " << eps << ' '
             << time.current() << ' ' << vals[1] << std::endl
             << "STEP44_CHECK vertex=(" << found_vertex << ") uy_vertex="
             << uy_vertex << " ux=" << vals[0] << " uz=" << vals[2]
             << std::endl;
          std::cout << tr.str() << std::flush;
        }
CPP

CC="$STAGE/step-44.cc"
grep -q '^        solution_n += solution_delta;$' "$CC" || { echo "patch anchor not found" >&2; exit 1; }
sed -i '/^        solution_n += solution_delta;$/r '"$STAGE/trace_block.inc" "$CC"
sed -i 's|^#include <iostream>$|#include <iostream>\n#include <limits>\n#include <sstream>\n#include <cmath>|' "$CC"
grep -q 'STEP44_TRACE' "$CC" || { echo "trace patch failed" >&2; exit 1; }
for f in step-44.cc parameters.prm CMakeLists.txt trace_block.inc; do
  cmp -s "$STAGE/$f" "$SRC/$f" || cp "$STAGE/$f" "$SRC/$f"
done
rm -rf "$STAGE"

# ---------------------------------------------------------------- build
BUILD="$SCRATCH/build"
mkdir -p "$BUILD"
( cd "$BUILD" && nice -n "$NICE" cmake -DCMAKE_BUILD_TYPE=Release "$SRC" > cmake.log 2>&1 \
  && nice -n "$NICE" make -j1 > make.log 2>&1 ) \
  || { echo "build failed, see $BUILD/make.log" >&2; tail -30 "$BUILD"/*.log >&2; exit 1; }
grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$BUILD/CMakeCache.txt" \
  || { echo "build is not Release" >&2; exit 1; }
EXE="$BUILD/step-44"
[[ -x "$EXE" ]] || { echo "no executable $EXE" >&2; exit 1; }

# ---------------------------------------------------------------- runs
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

prepare_one() {  # prepare_one <refinement> <static_cond>  -> prints run dir
  local R=$1 SC=$2
  local RUN="$SCRATCH/run_R${R}_sc${SC}"
  mkdir -p "$RUN"
  sed -e 's/^\( *set Polynomial degree *=\).*/\1 1/' \
      -e 's/^\( *set Quadrature order *=\).*/\1 2/' \
      -e 's/^\( *set Global refinement *=\).*/\1 '"$R"'/' \
      -e 's/^\( *set Use static condensation *=\).*/\1 '"$SC"'/' \
      "$SRC/parameters.prm" > "$RUN/parameters.prm"
  grep -Eq 'Polynomial degree *= 1$' "$RUN/parameters.prm"
  grep -Eq 'Quadrature order *= 2$' "$RUN/parameters.prm"
  grep -Eq "Global refinement *= $R\$" "$RUN/parameters.prm"
  grep -Eq "Use static condensation *= $SC\$" "$RUN/parameters.prm"
  echo "$RUN"
}

if [[ -n "$PREPARE_ONLY" ]]; then
  echo "STEP44_EXE $EXE"
  for R in $LEVELS; do
    RUN=$(prepare_one "$R" "$STATIC_COND")
    echo "STEP44_RUN_DIR $R $RUN"
  done
  exit 0
fi

run_one() {  # run_one <refinement> <static_cond>  -> prints run dir
  local R=$1 SC=$2
  local RUN
  RUN=$(prepare_one "$R" "$SC")
  local t0 t1
  t0=$(date +%s.%N)
  ( cd "$RUN" && nice -n "$NICE" "$EXE" > step44.log 2>&1 ) \
    || { echo "step-44 failed for R=$R sc=$SC, see $RUN/step44.log" >&2; tail -20 "$RUN/step44.log" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f\n", b-a}' > "$RUN/wall_seconds"
  rm -f "$RUN"/solution-*.vtu
  echo "$RUN"
}

summarise() {  # summarise <run dir> -> "dofs,wall,newton,cg" (counting: summarise_log.awk)
  local RUN=$1 counts
  counts=$(awk -f "$REPO_DIR/bench/step44_dealii/summarise_log.awk" "$RUN/step44.log")
  echo "${counts%%,*},$(cat "$RUN/wall_seconds"),${counts#*,}"
}

CSV="$RESULTS_DIR/step44_dealii.csv"
TCSV="$RESULTS_DIR/step44_dealii_timing.csv"
mkdir -p "$RESULTS_DIR"
TMP_CSV="$SCRATCH/step44_dealii.csv"; TMP_TCSV="$SCRATCH/step44_dealii_timing.csv"
echo "elements_per_side,time,uy_top_centre_m" > "$TMP_CSV"
echo "elements_per_side,dofs,wall_seconds,newton_iterations_total,cg_iterations_total" > "$TMP_TCSV"

for R in $LEVELS; do
  echo "running R=$R (static condensation $STATIC_COND) ..."
  RUN=$(run_one "$R" "$STATIC_COND")
  EPS=$(( 1 << (R > 1 ? R : 1) ))
  awk '/^STEP44_TRACE/ { printf "%s,%.10g,%s\n", $2, $3, $4 }' "$RUN/step44.log" >> "$TMP_CSV"
  echo "$EPS,$(summarise "$RUN")" >> "$TMP_TCSV"
  tail -1 "$TMP_TCSV"
  cp "$TMP_CSV" "$CSV"; cp "$TMP_TCSV" "$TCSV"   # keep partial results
done

# ------------------------------------------------ static condensation cross-check
OTHER=$([[ "$STATIC_COND" == true ]] && echo false || echo true)
for R in $SC_COMPARE; do
  echo "cross-check R=$R with static condensation $OTHER ..."
  RUN_A="$SCRATCH/run_R${R}_sc${STATIC_COND}"
  [[ -f "$RUN_A/step44.log" ]] || RUN_A=$(run_one "$R" "$STATIC_COND")
  RUN_B=$(run_one "$R" "$OTHER")
  echo "  sc=$STATIC_COND: $(summarise "$RUN_A")   sc=$OTHER: $(summarise "$RUN_B")  (dofs,wall,newton,cg)"
  paste -d' ' <(grep '^STEP44_TRACE' "$RUN_A/step44.log") <(grep '^STEP44_TRACE' "$RUN_B/step44.log") |
    awk '{ d = $4 - $8; if (d < 0) d = -d; r = d / ($4 < 0 ? -$4 : $4); if (r > m) m = r }
         END { printf "  max relative difference in uy over all steps: %.3e\n", m }'
done

echo "wrote $CSV and $TCSV"
