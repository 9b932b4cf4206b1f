#!/usr/bin/env bash
# The readers of lib/io as the programs meet them (issue 15): inputs built to overflow counts,
# exhaust memory or flood the terminal give exit 2 and one short `tool: file:line: what` line,
# with bounded work (CPU time) and memory; '-' holds an OFF or an extended XYZ, told from the content.
# `readers_bad_input.sh --list` prints the cases; `readers_bad_input.sh CASE` runs one (ctest
# registers each). Needs CMP_BIN (the built programs) and CMP_SRC.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
percolate="$bin/percolate"
rndmesh="$bin/rndmesh"
shellpack="$bin/shellpack"
sc="$src/data/percolate/simple_cubic_4x4x4.xyz"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
enter_scratch_dir

# bounded TOOL STATUS PATTERN cmd...: within 20 s of CPU time and 200 MB, with a short message
# that holds no control byte.
bounded() {
  expect_bounded 20 200000 "$@"
  # the message is short and holds no control byte
  [ "$(wc -c <stderr.txt)" -lt 400 ] || fail "$*: message of $(wc -c <stderr.txt) bytes"
  ! LC_ALL=C grep -q '[[:cntrl:]]' <(tr -d '\n' <stderr.txt) || fail "$*: control bytes in the message"
}

case_off_shell_counts_wrapping_32_bits() {
  printf 'OFF\n# box 2 2 2\n# periodic 1 1 1\n# shells 3 2147483647 2147483647 5\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >wrap.off
  bounded percolate 2 "wrap.off:4: '# shells' vertex counts add up to 4294967299, but the file has 3 vertices" \
    "$percolate" wrap.off --delta 0.1
  bounded rndmesh 2 "wrap.off:4: '# shells' vertex counts add up to 4294967299" "$rndmesh" stats wrap.off -o out.csv
  printf 'OFF\n# shells 2 2000000000 2000000000\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >two.off
  bounded rndmesh 2 "two.off:2: .*add up to 4000000000" "$rndmesh" stats two.off -o out.csv
}
case_xyz_30_bytes_asking_for_terabytes() {
  printf '1048576\nProperties=a:R:1048576' >tb.xyz
  [ "$(wc -c <tb.xyz)" -eq 30 ] || fail "not the 30-byte file"
  bounded percolate 2 "tb.xyz:2: Properties ask for 1048576 fields per atom" "$percolate" tb.xyz --delta 0.1
  bounded shellpack 2 "tb.xyz:2: Properties ask for 1048576 fields" "$shellpack" structure tb.xyz -o out.csv
  printf '2000000000\nProperties=species:S:1:pos:R:3:radius:R:1\nX 0 0 0 1\n' >many.xyz
  bounded percolate 2 "many.xyz:1: the frame claims 2000000000 atoms" "$percolate" many.xyz --delta 0.1
}
case_counts_from_a_pipe_grow_as_lines_arrive() {
  # From a pipe no size is known: memory follows the lines read, not the counts claimed.
  printf '2000000000\nLattice="1 0 0 0 1 0 0 0 1" Properties=species:S:1:pos:R:3:radius:R:1\nX 0 0 0 0.1\n' >many.xyz
  cli_tool=percolate
  bounded percolate 2 "<stdin>:3: unexpected end of file: expected 2000000000 atoms" \
    bash -c "cat many.xyz | '$percolate' - --delta 0.1"
  printf 'OFF\n# box 1 1 1\n2000000000 2000000000 0\n0 0 0\n' >big.off
  bounded percolate 2 "<stdin>:4: unexpected end of file: expected 2000000000 vertices" \
    bash -c "cat big.off | '$percolate' - --delta 0.1"
  mkfifo fifo.off
  (cat big.off >fifo.off &)
  bounded rndmesh 2 "fifo.off:4: unexpected end of file: expected 2000000000 vertices" "$rndmesh" stats fifo.off -o out.csv
}
case_dev_zero_and_a_sparse_file() {
  bounded percolate 2 "/dev/zero:1: line longer than 1048576 bytes" "$percolate" /dev/zero --delta 0.1
  bounded shellpack 2 "/dev/zero:1: line longer than 1048576 bytes" "$shellpack" structure /dev/zero -o out.csv
  bounded rndmesh 2 "/dev/zero:1: line longer than 1048576 bytes" "$rndmesh" stats /dev/zero -o out.csv
  truncate -s 2G sparse.xyz
  bounded percolate 2 "sparse.xyz:1: line longer than 1048576 bytes" "$percolate" sparse.xyz --delta 0.1
}
case_junk_is_cut_and_escaped_in_messages() {
  { printf 'OFF\n3 1 0\n0 0 \033[2J'; head -c 500000 /dev/zero | tr '\0' 'x'; printf '\n'; } >junk.off
  bounded rndmesh 2 "junk.off:3: expected a coordinate, got '\\\\x1B\[2Jxxx*\.\.\.'" "$rndmesh" stats junk.off -o out.csv
}
case_zero_spheres_and_duplicates() {
  printf '0\nLattice="2 0 0 0 2 0 0 0 2" Properties=species:S:1:pos:R:3:radius:R:1\n' >zero.xyz
  bounded shellpack 2 "zero.xyz:1: the frame has no spheres" "$shellpack" structure zero.xyz -o out.csv
  bounded percolate 2 "zero.xyz:1: the frame has no spheres" "$percolate" zero.xyz --delta 0.1
  printf '2\nLattice="2 0 0 0 2 0 0 0 2" Properties=species:S:1:pos:R:3:radius:R:1\nX 1 1 1 0.5\nX 1 1 1 0.5\n' >dup.xyz
  bounded percolate 2 "dup.xyz:4: particle duplicates another one" "$percolate" dup.xyz --delta 0.1
}
case_strict_d0() {
  sed 's/D0=1/D0=2.0abc/' "$sc" >d0.xyz
  grep -q 'D0=2.0abc' d0.xyz || fail "fixture has no D0=1"
  bounded percolate 2 "d0.xyz:2: D0='2.0abc' is not a positive number" "$percolate" d0.xyz --delta 0.1
  sed 's/D0=1/D0=0x2/' "$sc" >hex.xyz
  bounded percolate 2 "hex.xyz:2: D0='0x2' is not a positive number" "$percolate" hex.xyz --delta 0.1
  printf 'OFF\n# box 2 2 2\n# D0=2.0abc\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >d0.off
  bounded percolate 2 "d0.off:3: D0='2.0abc' is not a positive number" "$percolate" d0.off --delta 0.1
}
case_dash_holds_an_off_or_an_xyz() {
  "$percolate" - --delta 0.1 -q <"$sc" >xyz.csv || fail "XYZ on stdin"
  grep -q '^-,0,spheres,64,' xyz.csv || fail "XYZ row: $(grep -v '^#' xyz.csv | tail -1)"
  printf 'OFF\n# box 3 3 3\n# periodic 1 1 1\n# shells 1 4\n4 4 0\n1 1 1\n2 1 1\n1 2 1\n1 1 2\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n' >tet.off
  "$percolate" - --delta 0.1 -q <tet.off >off.csv || fail "OFF on stdin"
  grep -q '^-,0,shells,1,' off.csv || fail "OFF row: $(grep -v '^#' off.csv | tail -1)"
  "$shellpack" -q jam -N 20 --seed 3 -o - --csv j.csv | "$percolate" - --delta 0.1 -q >jam.csv || fail "jam | percolate -"
  grep -q '^-,0,spheres,20,' jam.csv || fail "jam row: $(grep -v '^#' jam.csv | tail -1)"
  printf 'a,b\n1,2\n' >t.csv
  bounded percolate 2 "<stdin>:1: expected a packing: .*the content is CSV" bash -c "'$percolate' - --delta 0.1 <t.csv"
}

run_cases "$@"
