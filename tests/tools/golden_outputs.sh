#!/usr/bin/env bash
# Behaviour unchanged (issue 38): seeded commands of every program, their outputs' hashes
# (tests/support/golden_hash.py: version, timings and thread counts taken out) compared with
# the hashes recorded in tests/data/golden/CASE.txt. A reorganisation of the code must leave
# them as they are; a change that means to change results records them again, on purpose,
# with `make golden-record` (every case; GOLDEN_CASES='kcfit lbflow' for some), never under
# CI, and says why in its commit. The test itself never writes into tests/data/golden,
# whatever the environment holds: only `--record CASE FILE` (what make golden-record runs)
# writes the hashes, to FILE. `bash tests/tools/golden_outputs.sh --list` prints the cases.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
bin=$(cd "$bin" && pwd)
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
rndmesh="$bin/rndmesh" shellpack="$bin/shellpack" percolate="$bin/percolate"
lbflow="$bin/lbflow" kcfit="$bin/kcfit" jam2d="$bin/jam2d"
enter_scratch_dir

run() { "$@" 2>>stderr.log || fail "$* exited $?: $(tail -3 stderr.log)"; }

case_rndmesh() {
  run "$rndmesh" icosa --level 3 -o icosa.off -q
  run "$rndmesh" octa --level 2 -r 2.5 -o octa.off -q
  run "$rndmesh" random -n 200 --seed 7 --trace anneal.csv -o random.off -q
  run "$rndmesh" random -n 100 --seeds 1:3 --threads 2 -o 'seed_{seed}.off' -q
  run "$rndmesh" stats icosa.off random.off seed_2.off -o stats.csv
}
case_shellpack_jam() {
  run "$shellpack" jam -N 20 --seed 7 -o jammed.xyz -q >jam.csv
  run "$shellpack" jam -N 12 --seeds 1:4 --threads 2 -q >jam_stats.csv
  run "$shellpack" structure jammed.xyz --forces forces.csv --summary summary.csv -q >rdf.csv
}
case_shellpack_shell() {
  run "$rndmesh" icosa --level 3 -r 2.5 -o cell.off -q
  run "$shellpack" shell --mesh cell.off --model svk -E 25e6 --nu 0.333 -t 0.1 --pressure 2.5e5 -o inflated.off -q >inflate.csv
  run "$shellpack" shell --mesh cell.off -E 25e6 --nu 0.333 -t 0.1 --bending hinge-uniform --pressure 2.5e5 \
    --pressure-model volume --walls 5.4 --squeeze 0.2 --squeeze-steps 3 -o squeezed.off -q >plates.csv
  run "$shellpack" shell --list-models >models.csv
}
case_shellpack_compress() {
  run "$shellpack" jam -N 10 --seed 3 -o jammed.xyz -q >/dev/null
  run "$rndmesh" icosa --level 3 --radius 0.5 -o cell.off -q
  run "$shellpack" compress jammed.xyz --mesh cell.off --contact hertz-faces --step 0.02 --ftol 1e-4 \
    --phi 0.6,0.65 -o 'faces_{phi}.off' -q >faces.csv
  run "$shellpack" compress jammed.xyz --mesh cell.off --contact hertz-vertices --step 0.02 --ftol 1e-4 \
    --phi 0.6 -o 'vertices_{phi}.off' -q >vertices.csv
  run "$shellpack" compress jammed.xyz --mesh cell.off --walls --contact hertz-vertices --step 0.1 --ftol 1e-4 \
    --phi 0.3,0.4 -o 'walls_{phi}.off' -q >walls.csv
  run "$shellpack" analyze faces_*.off -q >analyze.csv
}
case_percolate() {
  local sc="$src/data/percolate/simple_cubic_4x4x4.xyz"
  run "$shellpack" jam -N 16 --seed 2 -o spheres.xyz -q >/dev/null
  run "$percolate" spheres.xyz --delta 0.05,0.1 --scale 1.2 -o 'cluster_{delta}.vtk' --csv percolate.csv -q
  run "$percolate" spheres.xyz --delta 0.1 --scale 1.0,1.3,1.6,1.75 -q --csv sweep.csv
  run "$percolate" sweep sweep.csv --bins 3 -o probability.csv
  run "$percolate" "$sc" --delta 0.1 --sphere-marking centre -q --csv sc.csv -o sc.vtk
}
case_lbflow() {
  run "$shellpack" jam -N 16 --seed 2 -o spheres.xyz -q >/dev/null
  run "$percolate" spheres.xyz --delta 0.1 --sphere-marking centre -q -o cluster.vtk --csv /dev/null
  run "$lbflow" cluster.vtk --refine 1 --vtk flow.vtk --history history.csv -q -o flow.csv
  run "$lbflow" spheres.xyz --delta 0.1 --refine 1 -q -o exact.csv
}
case_kcfit() {
  local d="$src/data/kcfit"
  run "$kcfit" "$d/flow_synthetic.csv" --model kc-percolation --loss log -o kc.csv
  run "$kcfit" "$d/flow_synthetic.csv" --model power --fix phi_c=0.141 --loss linear --bootstrap 50 --seed 1 -o power.csv
  run "$kcfit" "$d/flow_synthetic.csv" --model tortuosity -o tortuosity.csv
  run "$kcfit" "$d/percolation_synthetic.csv" --model sigmoid -o sigmoid.csv
  run "$kcfit" "$d/threshold_synthetic.csv" --model threshold --x delta --y phi_c -o threshold.csv
  run "$kcfit" --list-models >models.csv
}
case_jam2d() {
  run "$jam2d" grow --box 5 --seed 1 -o jammed.xyz -q >growth.csv
  run "$jam2d" grow --box 5 --seed 1 --dphi 0.05 --P0 0.001 -o packed.xyz -q --csv ''
  run "$jam2d" moduli jammed.xyz packed.xyz -o moduli.csv
  run "$jam2d" sweep --box 4 --seeds 1:3 --dphi 0,0.02 --P0 inf,0.001 -q >sweep.csv
}

case_jam2d_chamber() {
  run "$jam2d" chamber --width 4 --height 5 --mobility 2e3 --time 4 --every 0.05 --frame-every 1 --seed 3 -o run.xyz -q >series.csv
  run "$jam2d" chamber --width 4 --height 6 --mobility 1e3 --time 3 --every 0.05 --seed 2 --P0 0.05 --contact sticky \
    --attraction 0.05 --integrator euler -q >feedback.csv
  run "$jam2d" avalanches series.csv --distribution dist.csv -o drops.csv
}

# The hashes of every file the case wrote (its stderr log aside), in hashes.txt.
hash_outputs() {
  local files; files=$(find . -type f ! -name stderr.log ! -name stdout.txt ! -name stderr.txt | sed 's|^\./||' | LC_ALL=C sort)
  [ -n "$files" ] || fail "the case wrote nothing"
  # shellcheck disable=SC2086
  /usr/bin/python3 "$src/tests/support/golden_hash.py" --src "$src" $files >hashes.txt || fail "hashing failed"
}
# Compared with the recorded ones, which are only read.
check_hashes() {
  local case=$1 want="$src/tests/data/golden/$1.txt"
  [ -s "$want" ] || fail "no recorded hashes $want (make golden-record records them)"
  diff "$want" hashes.txt >diff.txt || fail "$case: outputs differ from the recorded ones (< recorded, > now):
$(cat diff.txt)"
}

if [ "${1:-}" = --list ]; then
  declare -F | sed -n 's/^declare -f case_//p'
  exit 0
fi
if [ "${1:-}" = --record ]; then  # --record CASE FILE: make golden-record's, never the test's
  [ $# -eq 3 ] || fail "usage: golden_outputs.sh --record CASE FILE"
  [ "${CI:-}" != true ] || fail "goldens are not recorded under CI (CI=true)"
  record_to=$3
  case $record_to in /*) ;; *) record_to="$OLDPWD/$record_to" ;; esac
  declare -F "case_$2" >/dev/null || fail "unknown case '$2'"
  "case_$2"
  hash_outputs
  cp hashes.txt "$record_to" || fail "cannot write $record_to"
  echo "recorded $record_to" >&2
  exit 0
fi
declare -F "case_${1:-}" >/dev/null || fail "unknown case '${1:-}'"
"case_$1"
hash_outputs
check_hashes "$1"
