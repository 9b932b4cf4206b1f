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
# stderr that starts with "$cli_tool: " and matches PATTERN, and leaves no output file (out.*,
# or a temporary .out.*) behind.
expect_error() {
  local want=$1 pattern=$2; shift 2
  "$@" >stdout.txt 2>stderr.txt; local got=$?
  [ "$got" -eq "$want" ] || fail "$* exited $got, expected $want; stderr: $(cat stderr.txt)"
  [ "$(wc -l <stderr.txt)" -eq 1 ] || fail "$*: not one line on stderr: $(cat stderr.txt)"
  grep -q "^$cli_tool: .*$pattern" stderr.txt || fail "$*: stderr lacks '$pattern': $(cat stderr.txt)"
  ! ls out.* .out.* 2>/dev/null | grep -q . || fail "$*: left a file behind: $(ls -a)"
}

run_cases() {
  local cases
  cases=$(declare -F | awk '{print $3}' | sed -n 's/^case_//p')
  if [ "${1:-}" = --list ]; then echo "$cases"; exit 0; fi
  declare -F "case_${1:-}" >/dev/null || { echo "unknown case '${1:-}'; cases: $(echo $cases)" >&2; exit 2; }
  "case_$1"
}
