#!/usr/bin/env bash
# make bench, shellpack: time per jammed packing (the thesis's full protocol) and one FIRE
# minimisation side by side with LAMMPS (Debian `lammps`: min_style fire, Hertz through
# pair_style table, the same start and the same per-particle force tolerance). Sourced by
# scripts/bench/run.sh ($bench, $out, $machine, $stamp). LAMMPS is installed from Debian when
# missing unless BENCH_INSTALL_REFERENCES=0.
echo "== shellpack jam as a user runs it: time per jammed packing, 1 thread" >&2
# The command a user types, with its defaults (rattler-free isostatic packings, tolerance
# 1e-15) where they are affordable, and with the acceptance rules relaxed (said in the row)
# where default packings are rare: at N = 256 most tries have rattlers (see the README).
jam_work=$(mktemp -d)
jam_row() {  # jam_row N SEEDS LABEL [extra options...]
  local n=$1 seeds=$2 label=$3
  shift 3
  local t0 t1
  t0=$(date +%s%N)
  "$build/bin/shellpack" jam -N "$n" --seeds "$seeds" --threads 1 -q --timings "$@" \
    -o "$jam_work/j_{seed}.xyz" --csv "$jam_work/jam.csv" 2>/dev/null
  t1=$(date +%s%N)
  /usr/bin/python3 - "$jam_work/jam.csv" "$n" "$label" "$(((t1 - t0) / 1000000))e-3" "shellpack jam -N $n --seeds $seeds --threads 1 $*" <<'PY'
import csv, sys
path, n, label, wall, command = sys.argv[1], int(sys.argv[2]), sys.argv[3], float(sys.argv[4]), sys.argv[5]
rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
k = len(rows)
its = sum(int(r["fire_iterations"]) for r in rows)
rejected = sum(int(r["rejected_tries"]) for r in rows)
phi = sum(float(r["phi_J"]) for r in rows) / k
print(f"jam,{n},{k},1e-15,{label},{wall / k:.4g},{wall:.4g},{its},{n * its / wall:.4g},{its / wall:.4g},{phi:.4f},{rejected / k:.2f},\"{command.strip()}\"")
PY
}
{
  bench_header
  echo "stage,N,packings,tolerance,accepted,seconds_per_packing,seconds,fire_iterations,particle_iterations_per_s,iterations_per_s,phi_J_mean,rejected_per_packing,command"
  jam_row 16 1:20 rattler_free_isostatic
  jam_row 50 1:10 rattler_free_isostatic
  jam_row 128 1:2 rattler_free_isostatic
  jam_row 256 1:2 any --keep-rattlers --allow-hyperstatic
  jam_row 1024 1:1 any --keep-rattlers --allow-hyperstatic
} | tee "$out/shellpack_jam.csv" >&2
rm -rf "$jam_work"

if ! command -v lmp >/dev/null && [ "${BENCH_INSTALL_REFERENCES:-1}" = 1 ]; then
  echo "== installing the reference: Debian lammps" >&2
  if [ "$(id -u)" -eq 0 ]; then SUDO=; else SUDO=sudo; fi
  $SUDO apt-get install -y -qq --no-install-recommends lammps >&2 || echo "could not install lammps" >&2
fi
echo "== shellpack FIRE vs LAMMPS FIRE: Hertzian spheres at phi = 0.66 from random centres, max|f_i| <= 1e-12, one core" >&2
work=$(mktemp -d)
lammps_version=absent
if command -v lmp >/dev/null; then  # lmp -h exits non-zero: keep it out of pipefail's way
  lammps_version=$( (lmp -h 2>/dev/null || true) | grep -m1 -o 'Simulator - .*' | sed 's/Simulator - //')
fi
{
  bench_header
  echo "# lammps=$lammps_version"
  echo "N,phi,tolerance,ours_iterations,ours_seconds,ours_particle_iterations_per_s,lammps_iterations,lammps_seconds,lammps_particle_iterations_per_s,speedup_time,speedup_per_iteration"
  for n in 50 256 1024; do
    ours=$(OMP_NUM_THREADS=1 "$bench/bench_spheres" fire $n 0.66 1e-12 1 "$work/start.data" "$work/hertz.table")
    it=$(cut -d, -f6 <<<"$ours"); s=$(cut -d, -f7 <<<"$ours")
    if command -v lmp >/dev/null; then
      cat >"$work/in.fire" <<LMP
units lj
atom_style atomic
boundary p p p
read_data $work/start.data
pair_style table linear 100000
pair_coeff 1 1 $work/hertz.table HERTZ
neighbor 0.2 bin
neigh_modify every 1 delay 0 check yes
timestep 0.1
min_style fire
min_modify norm max
minimize 0 1e-12 10000000 10000000
LMP
      (cd "$work" && OMP_NUM_THREADS=1 lmp -in in.fire -screen none -log log.lammps >/dev/null)
      lit=$(awk '/Iterations, force evaluations/ { print $(NF-1) }' "$work/log.lammps")
      ls=$(awk '/^Loop time of/ { print $4 }' "$work/log.lammps")
    else
      lit=NaN; ls=NaN
    fi
    awk -v n=$n -v it="$it" -v s="$s" -v lit="$lit" -v ls="$ls" 'BEGIN {
      printf "%d,0.66,1e-12,%d,%.4f,%.4g,%s,%s,%.4g,%.2f,%.2f\n", n, it, s, n * it / s, lit, ls,
             (ls > 0 ? n * lit / ls : 0), (ls > 0 ? ls / s : 0), (ls > 0 ? (n * it / s) / (n * lit / ls) : 0) }'
  done
} | tee "$out/shellpack_fire_lammps.csv" >&2
rm -rf "$work"

echo "== shellpack FIRE on large systems, 1 and 2 threads (the chunked parallel force loop and FIRE passes)" >&2
{
  bench_header
  echo "N,threads,iterations,seconds,particle_iterations_per_s"
  for n in 1024 4096 16384; do
    for t in 1 2; do
      OMP_NUM_THREADS=$t "$bench/bench_spheres" fire $n 0.66 1e-12 1 |
        awk -F, -v t=$t '{ printf "%d,%d,%d,%.4f,%.4g\n", $2, t, $6, $7, $8 }'
    done
  done
} | tee "$out/shellpack_fire_threads.csv" >&2
