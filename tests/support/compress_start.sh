# Shared by the shellpack compress test scripts (sourced after cli_harness.sh, with $shellpack
# and $rndmesh set): the start of every run and the readers of its tables.
# make_start: a jammed packing of 16 spheres and an icosahedral cell of 162 vertices.
make_start() {
  "$shellpack" jam -N 16 --seed 3 -o jammed.xyz -q >/dev/null || fail "jam"
  "$rndmesh" icosa --level 3 -o cell.off -q || fail "rndmesh"
}
# col CSV NAME: the values of a column (header by name, # lines skipped); key FILE NAME: a
# `# NAME=value` line's value.
col() { awk -F, -v c="$2" '/^#/ { next } !h { for (i = 1; i <= NF; i++) if ($i == c) k = i; h = 1; next } { print $k }' "$1"; }
key() { sed -n "s/^# $2=//p" "$1"; }
