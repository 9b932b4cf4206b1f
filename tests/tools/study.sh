#!/usr/bin/env bash
# The study campaign (scripts/study/study.mk) at its tiny size, as `make study` runs it: the
# hand-offs between the stages (compress -> percolate -> lbflow -> kcfit), a campaign killed
# half-way and run again, the variables checked before any work, a failed step retried, the
# jobs printed for GNU parallel with make study-status before and after, and a report that
# refuses results of another version.
#   bash study.sh --list | CASE     (needs CMP_BIN, CMP_SRC)
set -uo pipefail
cases="handoffs parallel_through_top_makefile kill_and_resume bad_variables failed_step_retried jobs_for_parallel status_time_left mixed_versions_refused missing_tools_named"
if [[ ${1:-} == --list ]]; then printf '%s\n' $cases; exit 0; fi
case=${1:?CASE}
bin=${CMP_BIN:?set CMP_BIN}
src=${CMP_SRC:?set CMP_SRC}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export OMP_NUM_THREADS=1
campaign() { make -C "$src" -f scripts/study/study.mk --no-print-directory STUDY=tiny STUDY_DIR="$1" \
  BUILD="$(dirname "$bin")" THREADS=1 "${@:2}"; }
rows() { grep -v '^#' "$1" | tail -n +2 | wc -l; }

case_handoffs() {
  campaign "$tmp/st" -j2 all >"$tmp/log" 2>&1 || fail "campaign: $(tail -20 "$tmp/log")"
  [ -s "$tmp/st/report.html" ] || fail "no report"
  for f in fig5_2bc fig5_2d fig5_3 fig5_4 fig5_5 ch4_structure; do
    [ -s "$tmp/st/figures/$f.png" ] || fail "no figure $f"
  done
  /usr/bin/python3 - "$tmp/st" <<'PY' || fail "hand-offs"
import csv, glob, math, os, sys
d = sys.argv[1]
def rows(p):
    return list(csv.DictReader(l for l in open(p) if not l.startswith("#")))
def meta(p):
    return dict(l[1:].strip().split("=", 1) for l in open(p) if l.startswith("#") and "=" in l)
perc = rows(f"{d}/tables/percolate.csv")
flow = rows(f"{d}/tables/flow.csv")
assert perc and flow, "empty tables"
checked = 0
for r in perc:
    comp = {float(c["phi"]): c for c in rows(f"{d}/compress/{r['run']}/compress.csv")}
    phi = float(r["phi_target"])
    # percolate's porosity of the packing is 1 - sum V_shell / V_box of compress's output: the
    # shells are within compress's 0.1 % volume band of V0, phi = sum V0 / L^3
    assert abs(float(r["porosity"]) - (1 - phi)) <= 1.5e-3 * phi, (r["porosity"], phi)
    # the voxels: the percolating cluster holds only voxels that no triangle touches, outside every
    # shell, so its volume lies below the porosity, by at most a layer of sqrt(3) delta over the
    # shells' area (spheres of D0 as the bound's area) plus the pockets it does not reach
    n, delta = int(r["particles"]), float(r["delta"])
    layer = n * math.pi * math.sqrt(3) * delta / (n * math.pi / 6 / phi)
    cf = float(r["cluster_fraction"])
    assert cf <= float(r["porosity"]) + 1e-12, (cf, r["porosity"])
    assert r["percolates"] == "0" or cf >= float(r["porosity"]) - layer - 0.1, (cf, r["porosity"], layer)
    checked += 1
for f in flow:
    p = [r for r in perc if r["run"] == f["run"] and r["phi_target"] == f["phi_target"]
         and abs(float(r["delta"]) - float(f["delta"])) < 1e-12]
    assert len(p) == 1, f
    p = p[0]
    # lbflow read exactly the cluster percolate wrote: the same grid and the same fluid voxels
    assert (f["nx"], f["ny"], f["nz"]) == (p["nx"], p["ny"], p["nz"]), (f, p)
    assert int(f["fluid_nodes"]) == int(p["cluster_voxels"]) * int(f["refine"]) ** 3, (f["fluid_nodes"], p["cluster_voxels"])
    assert abs(float(f["porosity"]) - float(p["porosity"])) < 1e-12
# every percolating cluster at FLOW_DELTA went through lbflow, and no other
perc_flow = [r for r in perc if r["percolates"] == "1" and abs(float(r["delta"]) - 0.1) < 1e-12]
assert len(perc_flow) == len(flow), (len(perc_flow), len(flow))
# the fits used every point they were given: kcfit's n is the table's count; kcfit refuses fewer
# points than the tortuosity's 2 free parameters plus one (issue 58), and then writes no fit
tortuosity = f"{d}/fits/tortuosity_M1.csv"
if len(flow) >= 3:
    fit = meta(tortuosity)
    assert int(fit["n"]) == len(flow), (fit["n"], len(flow))
else:
    assert not os.path.exists(tortuosity), f"a tortuosity fit of {len(flow)} points"
sig = meta(f"{d}/fits/hydraulic_radius.csv")
assert int(sig["n"]) == len(perc_flow), (sig["n"], len(perc_flow))
print(f"{checked} percolate rows, {len(flow)} flows checked")
PY
}

# `make study -j2` hands its job slots down to the campaign's sub-makes (a recipe that calls make
# through a variable needs the '+' prefix, or the campaign silently runs one task at a time).
case_parallel_through_top_makefile() {
  make -C "$src" --no-print-directory -j2 -o study-tools study STUDY=tiny STUDY_DIR="$tmp/st" \
    BUILD="$(dirname "$bin")" THREADS=1 >"$tmp/log" 2>&1 || fail "make study: $(tail -20 "$tmp/log")"
  ! grep -i 'jobserver unavailable' "$tmp/log" || fail "the campaign ran without the job server"
  [ -s "$tmp/st/report.html" ] || fail "no report"
}

case_kill_and_resume() {
  campaign "$tmp/st" all >"$tmp/log" 2>&1 || fail "uninterrupted: $(tail -20 "$tmp/log")"
  mkdir "$tmp/whole" && cp "$tmp"/st/tables/*.csv "$tmp/whole/" || fail "tables"
  total=$(wc -l <"$tmp/st/log/recipes.log")
  rm -rf "$tmp/st"
  # make itself in the background (not a shell around it), as a user's `kill` finds it
  ( exec make -C "$src" -f scripts/study/study.mk --no-print-directory STUDY=tiny STUDY_DIR="$tmp/st" \
      BUILD="$(dirname "$bin")" THREADS=1 all >"$tmp/log1" 2>&1 ) &
  pid=$!
  for _ in $(seq 600); do [ -s "$tmp/st/log/compress.csv" ] && break; sleep 0.1; done
  [ -s "$tmp/st/log/compress.csv" ] || fail "no compression finished in 60 s"
  kill -TERM "$pid"
  wait "$pid" && fail "make should stop on SIGTERM"
  sleep 0.5
  pgrep -f "$tmp/st/bin/" >/dev/null && fail "a program of the campaign outlived make: $(pgrep -af "$tmp/st/bin/")"
  [ -s "$tmp/st/report.html" ] && fail "the killed campaign should not have reached its report"
  # finished: logged as done and still there (make removes the target of a recipe it had not yet
  # reaped when the signal came, as for any interrupted recipe)
  done_before=$(for t in $(cut -d, -f2 "$tmp"/st/log/*.csv | sort -u); do [ -e "$t" ] && echo "$t"; done)
  started_before=$(wc -l <"$tmp/st/log/recipes.log")
  campaign "$tmp/st" all >"$tmp/log2" 2>&1 || fail "rerun: $(tail -20 "$tmp/log2")"
  for f in "$tmp"/whole/*.csv; do
    cmp -s "$f" "$tmp/st/tables/$(basename "$f")" || fail "$(basename "$f") differs after the resume: $(diff "$f" "$tmp/st/tables/$(basename "$f")" | head -5)"
  done
  rerun=$(tail -n +$((started_before + 1)) "$tmp/st/log/recipes.log" | cut -d' ' -f2)
  for t in $done_before; do
    grep -qx "$t" <<<"$rerun" && fail "$t was finished before the kill and made again"
  done
  n_rerun=$(wc -l <<<"$rerun")
  n_done=$(wc -w <<<"$done_before")
  [ "$n_rerun" -le $((total - n_done)) ] || fail "the rerun ran $n_rerun recipes, the campaign has $total, $n_done were done"
  echo "killed after $n_done finished recipes; the rerun ran $n_rerun of $total"
}

case_bad_variables() {
  campaign "$tmp/st" all N='16 3' DELTA=0 REFINE=0 PHI=0.9:0.8:0.1 >"$tmp/out" 2>&1 && fail "bad variables accepted"
  for want in "study: N: '3' is not a shell count" "study: DELTA: '0' must lie in" "study: REFINE: '0' is not a refinement" \
      "study: PHI: '0.9:0.8:0.1' is an empty range"; do
    grep -q "$want" "$tmp/out" || fail "no line '$want': $(cat "$tmp/out")"
  done
  [ "$(grep -c '^study:' "$tmp/out")" = 4 ] || fail "one line per problem: $(cat "$tmp/out")"
  [ -e "$tmp/st" ] && fail "work started: $(ls -R "$tmp/st" | head)"
  return 0
}

case_failed_step_retried() {
  campaign "$tmp/st" stage-compress COMPRESS_OPTS='--ftol 1e-4 --fire-max-iterations 3' >"$tmp/out" 2>&1 &&
    fail "a capped relaxation should fail the step"
  ls "$tmp"/st/compress/N10_s*/compress.csv 2>/dev/null && fail "a failed compression left its table"
  campaign "$tmp/st" stage-compress >"$tmp/out2" 2>&1 || fail "retry: $(tail -5 "$tmp/out2")"
  for s in 1 2; do
    [ -s "$tmp/st/compress/N10_s$s/compress.csv" ] || fail "seed $s not retried"
    [ -e "$tmp/st/compress/N10_s$s/run.ckpt" ] && fail "a finished compression left its checkpoint"
    grep -q -- "--fire-max-iterations 3" "$tmp/st/compress/N10_s$s/compress.csv" && fail "retried with the old arguments"
  done
  return 0
}

case_jobs_for_parallel() {
  command -v parallel >/dev/null || fail "GNU parallel is not installed (make deps installs it)"
  campaign "$tmp/st" jobs STAGE=compress >"$tmp/out" 2>&1 && fail "compress jobs before the jams"
  grep -q "STAGE=compress needs stage jam finished first" "$tmp/out" || fail "$(cat "$tmp/out")"
  # make study-status before any work: every target to do, no time yet, the flow's total unknown
  campaign "$tmp/st" status >"$tmp/status" 2>"$tmp/err" || fail "status: $(cat "$tmp/err")"
  for want in "stage,done,total,seconds,mean_seconds,seconds_left" "jam,0,2,0,," "compress,0,2,0,," \
      "percolate,0,8,0,," "flow,0,0,0,,"; do
    grep -qx "$want" "$tmp/status" || fail "status: no row '$want': $(cat "$tmp/status")"
  done
  grep -q "study: flow: the total counts the clusters found by the 0 of 8 percolate rows" "$tmp/err" ||
    fail "status: no word on the flow's unknown total: $(cat "$tmp/err")"
  for stage in jam compress analyze percolate flow; do
    campaign "$tmp/st" jobs STAGE=$stage >"$tmp/$stage.txt" 2>"$tmp/err" || fail "jobs $stage: $(cat "$tmp/err")"
    [ -s "$tmp/$stage.txt" ] || fail "no $stage jobs"
    (cd "$src" && parallel -j2 <"$tmp/$stage.txt") >/dev/null 2>&1 || fail "parallel $stage"
  done
  [ "$(wc -l <"$tmp/compress.txt")" = 2 ] || fail "one compress job per (N, seed): $(cat "$tmp/compress.txt")"
  [ "$(wc -l <"$tmp/percolate.txt")" = 8 ] || fail "one percolate job per (packing, delta): $(wc -l <"$tmp/percolate.txt")"
  before=$(wc -l <"$tmp/st/log/recipes.log")
  campaign "$tmp/st" all >"$tmp/out" 2>&1 || fail "report after parallel: $(tail -5 "$tmp/out")"
  [ "$(wc -l <"$tmp/st/log/recipes.log")" = "$before" ] || fail "make redid what parallel had done: $(tail -n +$((before + 1)) "$tmp/st/log/recipes.log")"
  [ -s "$tmp/st/report.html" ] || fail "no report"
  # and when all is done: every stage finished, its seconds those of timed.sh's log, nothing left
  campaign "$tmp/st" status >"$tmp/status" 2>"$tmp/err" || fail "status: $(cat "$tmp/err")"
  [ -s "$tmp/err" ] && fail "status of a finished campaign: $(cat "$tmp/err")"
  /usr/bin/python3 - "$tmp/status" "$tmp/st/log" <<'PY' || fail "status at the end: $(cat "$tmp/status")"
import csv, sys
rows = {r["stage"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert list(rows) == ["mesh", "jam", "compress", "analyze", "percolate", "flow"], list(rows)
for stage, r in rows.items():
    assert int(r["done"]) == int(r["total"]) > 0, r
    last = {l.split(",")[1]: float(l.split(",")[2]) for l in open(f"{sys.argv[2]}/{stage}.csv")}
    assert abs(float(r["seconds"]) - sum(last.values())) < 0.1, (r, last)
    assert r["seconds_left"] == "0", r
assert int(rows["compress"]["total"]) == 2 and int(rows["percolate"]["total"]) == 8, rows
PY
}

case_status_time_left() {
  # make study-status's time left (stage_status.sh): a target still to do counts at the mean of
  # the finished ones of its N (and M), else at their seconds per shell times its N (of its M),
  # else at the mean of all; the last run of a target is the one that counts
  local st=$src/scripts/study/stage_status.sh
  printf '%s\n' compress,/N1_x/compress/N10_s1/compress.csv,100 compress,/N1_x/compress/N10_s1/compress.csv,90 \
    compress,/N1_x/compress/N10_s2/compress.csv,110 >"$tmp/compress.csv"
  # 2 of N = 10 at 100 s and 1 of N = 20 at 10 s a shell: 400 s
  [ "$("$st" compress 2 5 "$tmp/compress.csv" 10,0:2 20,0:1)" = "compress,2,5,200.0,100.0,400" ] ||
    fail "compress: $("$st" compress 2 5 "$tmp/compress.csv" 10,0:2 20,0:1)"
  printf '%s\n' flow,/d/flow/N10_s1/M1/0.8.csv,10 flow,/d/flow/N10_s1/M2/0.8.csv,80 >"$tmp/flow.csv"
  # N = 10 at M = 1: 10 s; N = 20 at M = 2: 8 s a shell, 160 s; M = 3, never run: the mean, 45 s
  [ "$("$st" flow 2 5 "$tmp/flow.csv" 10,1:1 20,2:1 10,3:1)" = "flow,2,5,90.0,45.0,215" ] ||
    fail "flow: $("$st" flow 2 5 "$tmp/flow.csv" 10,1:1 20,2:1 10,3:1)"
  # nothing finished: no time, no guess
  [ "$("$st" flow 0 2 "$tmp/none.csv" 10,1:2)" = "flow,0,2,0,," ] || fail "nothing done: $("$st" flow 0 2 "$tmp/none.csv" 10,1:2)"
  # and make study-status writes nothing, not even the parameters' stamps
  campaign "$tmp/fresh" status >"$tmp/status" 2>"$tmp/err" || fail "status: $(cat "$tmp/err")"
  grep -qx "compress,0,2,0,," "$tmp/status" || fail "status of a fresh campaign: $(cat "$tmp/status")"
  [ -e "$tmp/fresh" ] && fail "make study-status wrote into the campaign: $(ls -R "$tmp/fresh")"
  return 0
}

case_mixed_versions_refused() {
  campaign "$tmp/st" structure >"$tmp/out" 2>&1 || fail "campaign: $(tail -5 "$tmp/out")"
  f="$tmp/st/perc/N10_s2/d0.1/0.8.csv"
  sed -i 's/^# provenance=percolate [^:]*:/# provenance=percolate 0.0.9-old:/' "$f"
  campaign "$tmp/st" report >"$tmp/out" 2>&1 && fail "a report mixing versions"
  grep -q "percolate: made by 2 versions of the program" "$tmp/out" || fail "$(cat "$tmp/out")"
  grep -q "0.0.9-old (1 files, e.g. $f)" "$tmp/out" || fail "the odd file is not named: $(cat "$tmp/out")"
  [ -e "$tmp/st/report.html" ] && fail "a report was written"
  ALLOW_MIXED=1 campaign "$tmp/st" report >"$tmp/out" 2>&1 || fail "ALLOW_MIXED: $(tail -5 "$tmp/out")"
  grep -q "Mixed campaign" "$tmp/st/report.html" || fail "the report does not say it is mixed"
}

case_missing_tools_named() {
  campaign "$tmp/st" all BUILD=/nonexistent >"$tmp/out" 2>&1 && fail "a campaign without programs"
  grep -q "study: /nonexistent/bin/[a-z]* is missing: build the programs first (make study-tools)" "$tmp/out" ||
    fail "$(cat "$tmp/out")"
  mkdir "$tmp/path"   # a PATH without xvfb-run or srun
  env -i PATH="$tmp/path" /bin/bash "$src/scripts/study/check_tools.sh" 'srun -N1 -n1' >"$tmp/out" 2>&1 && fail "nothing missing?"
  grep -q "study: xvfb-run .* is missing: apt-get install xvfb xauth (or make deps)" "$tmp/out" || fail "$(cat "$tmp/out")"
  grep -q "study: srun (RUN=srun -N1 -n1) is missing: apt-get install slurm-client (or make deps)" "$tmp/out" || fail "$(cat "$tmp/out")"
  [ "$(wc -l <"$tmp/out")" = 2 ] || fail "only those two: $(cat "$tmp/out")"
}

"case_$case"
