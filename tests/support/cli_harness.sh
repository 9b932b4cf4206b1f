# Shared by the shell tests of tests/tools (sourced, not run): a program as a user runs it.
#   source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
#   cli_tool=shellpack          # the name every message of the program starts with
#   enter_scratch_dir           # a temporary working folder, removed at exit
#   case_x() { ...; expect_error 2 "pattern" "$prog" args...; }
#   run_cases "$@"              # --list prints the cases; CASE runs one (ctest registers each)

fail() { echo "FAIL: $*" >&2; exit 1; }

enter_scratch_dir() {
  cli_scratch=$(mktemp -d)
  trap 'rm -rf "$cli_scratch"' EXIT
  cd "$cli_scratch" || exit 1
}

# expect_error STATUS PATTERN cmd...: the command fails with STATUS and exactly one line on
# stderr that starts with "$cli_tool: " and matches PATTERN (besides the hint line "$cli_tool:
# run '... --help' for the options" that usage errors end with), and leaves no output file
# (out.*, or a temporary .out.*) behind.
expect_error() {
  local want=$1 pattern=$2; shift 2
  "$@" >stdout.txt 2>stderr.txt; local got=$?
  [ "$got" -eq "$want" ] || fail "$* exited $got, expected $want; stderr: $(cat stderr.txt)"
  [ "$(grep -vc "^$cli_tool: run '.* --help' for the options\$" stderr.txt)" -eq 1 ] ||
    fail "$*: not one line on stderr: $(cat stderr.txt)"
  grep -q "^$cli_tool: .*$pattern" stderr.txt || fail "$*: stderr lacks '$pattern': $(cat stderr.txt)"
  ! ls out.* .out.* 2>/dev/null | grep >/dev/null . || fail "$*: left a file behind: $(ls -a)"
}

# lacks [-i] WHY PATTERN FILE...: no line of any FILE matches PATTERN (grep; -i: ignoring case).
# A negative check says something only about a run that succeeded and wrote its file, so call
# it after checking the run's status; a missing or empty FILE fails, as does a grep error:
# `grep -q PATTERN FILE && fail` passed when the program had crashed and written nothing.
lacks() {
  local opt=()
  [ "$1" = -i ] && { opt=(-i); shift; }
  local why=$1 pattern=$2 f got; shift 2
  for f in "$@"; do
    [ -s "$f" ] || fail "$why: $f is missing or empty: nothing to search"
    grep -q "${opt[@]}" -- "$pattern" "$f"; got=$?
    [ "$got" -ne 0 ] || fail "$why: $f: $(grep -m3 "${opt[@]}" -- "$pattern" "$f")"
    [ "$got" -eq 1 ] || fail "$why: grep failed on $f"
  done
}

# same_lines WHY DROP A B: A and B are byte for byte the same once the lines matching DROP
# (grep -v) are taken out, and something remains of each: `cmp <(grep -v X a) <(grep -v X b)`
# compared empty with empty when both files were missing.
same_lines() {
  local why=$1 drop=$2 a=$3 b=$4 f
  for f in "$a" "$b"; do [ -s "$f" ] || fail "$why: $f is missing or empty"; done
  local ka kb d
  ka=$(mktemp "${cli_scratch:-${TMPDIR:-/tmp}}/.same_a.XXXXXX") && kb=$(mktemp "${cli_scratch:-${TMPDIR:-/tmp}}/.same_b.XXXXXX") ||
    fail "$why: mktemp"
  grep -v -- "$drop" "$a" >"$ka"
  grep -v -- "$drop" "$b" >"$kb"
  if [ ! -s "$ka" ] || [ ! -s "$kb" ]; then
    rm -f "$ka" "$kb"
    fail "$why: nothing is left of $a or $b without the lines matching '$drop'"
  fi
  if ! cmp -s "$ka" "$kb"; then
    d=$(diff "$ka" "$kb" | head -6)
    rm -f "$ka" "$kb"
    fail "$why: $a and $b differ: $d"
  fi
  rm -f "$ka" "$kb"
}

# on_terminal OUT cmd...: runs cmd with stdin, stdout and stderr on a new pseudo-terminal
# (CI has none: this makes one), writes what the terminal received to OUT, returns cmd's status.
on_terminal() {
  local out=$1; shift
  /usr/bin/python3 - "$out" "$@" <<'PY'
import os, pty, sys
out, argv = sys.argv[1], sys.argv[2:]
pid, fd = pty.fork()
if pid == 0:
    os.execvp(argv[0], argv)
data = b""
while True:
    try:
        chunk = os.read(fd, 65536)
    except OSError:
        break
    if not chunk:
        break
    data += chunk
_, status = os.waitpid(pid, 0)
open(out, "wb").write(data)
sys.exit(os.waitstatus_to_exitcode(status) if hasattr(os, "waitstatus_to_exitcode") else status >> 8)
PY
}

# wait_ready PID FILE: waits until FILE exists (a program given CMP_READY_FILE=FILE creates it
# when its options are checked and its work starts: lib/cli/interrupt.hpp); fails if process
# PID ends first. No deadline: a blocked program is left to ctest's timeout, and a slow or
# loaded machine only makes the wait longer.
wait_ready() {
  local pid=$1 file=$2
  until [ -e "$file" ]; do
    kill -0 "$pid" 2>/dev/null || [ -e "$file" ] || fail "the program ended before its work started"
    sleep 0.01
  done
}

# interrupt_run SIGNAL cmd...: starts cmd in the background (job control on, so SIGINT is not
# ignored as it is for background jobs of a script), sends SIGNAL once cmd says that its work
# started (CMP_READY_FILE, created outside the working folder: wait_ready), and returns cmd's
# exit status; its stderr goes to interrupt.err. The run must be long enough not to end
# between the two.
interrupt_run() {
  local sig=$1; shift
  local ready
  ready=$(mktemp -u "${TMPDIR:-/tmp}/cmp_ready.XXXXXX")
  set -m
  CMP_READY_FILE=$ready "$@" >/dev/null 2>interrupt.err &
  local pid=$!
  wait_ready "$pid" "$ready"
  rm -f "$ready"
  kill -s "$sig" "$pid"
  wait "$pid"; local got=$?
  set +m
  return $got
}

# cpu_limited SECONDS cmd...: runs cmd with at most SECONDS of CPU time (ulimit -t; it dies by
# SIGXCPU beyond). A bound on work, not on the wall clock, so another process on the machine
# cannot make it fail; a program blocked without computing is left to ctest's timeout.
cpu_limited() {
  local seconds=$1
  shift
  (ulimit -t "$seconds" && exec "$@")
}

# expect_bounded SECONDS KB TOOL STATUS PATTERN cmd...: expect_error within SECONDS of CPU time
# (not of wall time: the machine's load cannot fail it) and below KB of peak memory (max RSS).
expect_bounded() {
  local seconds=$1 kb=$2
  cli_tool=$3
  local want=$4 pattern=$5
  shift 5
  expect_error "$want" "$pattern" cpu_limited "$seconds" /usr/bin/time -f %M -o rss.txt "$@"
  local rss
  rss=$(tail -1 rss.txt)
  [ "$rss" -lt "$kb" ] || fail "$*: used $rss kB"
}

# cluster_vtk: percolate's cluster image of one sphere in a periodic unit box at delta 0.125,
# c.vtk (needs $percolate).
cluster_vtk() {
  printf '1\nLattice="1 0 0 0 1 0 0 0 1" Properties=species:S:1:pos:R:3:radius:R:1 pbc="T T T" D0=1\nX 0.5 0.5 0.5 0.4\n' >sphere.xyz
  "$percolate" sphere.xyz --delta 0.125 -o c.vtk -q >p.csv || fail "percolate"
}

run_cases() {
  local cases
  cases=$(declare -F | awk '{print $3}' | sed -n 's/^case_//p')
  if [ "${1:-}" = --list ]; then echo "$cases"; exit 0; fi
  declare -F "case_${1:-}" >/dev/null || { echo "unknown case '${1:-}'; cases: $(echo $cases)" >&2; exit 2; }
  "case_$1"
}
