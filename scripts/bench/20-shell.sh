# Sourced by scripts/bench/run.sh: shell mechanics (bench/bench_shell.cpp) on 1 and 2 threads.
for threads in 1 2; do
  OMP_NUM_THREADS=$threads "$bench/bench_shell" | sed "s/^/$threads,/" 
done | { echo "threads,name,value,unit"; cat; } >"$out/shell.csv"
cat "$out/shell.csv" >&2
