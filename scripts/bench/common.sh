# Shared by the benchmarks of scripts/bench/ (sourced by run.sh before them, with $build and
# $out set): where the benchmark programs are, the machine and the date every CSV file
# records, and bench_header, which writes those two lines at the top of a CSV file.
bench="$build/bench"
machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores"
stamp="$(date -u +%Y-%m-%d)"
bench_header() {
  echo "# machine=$machine"
  echo "# date=$stamp"
}
