#!/usr/bin/env bash
# make bench, rndmesh and the neighbour machinery. Sourced by scripts/bench/run.sh, which sets
# $bench (the benchmark programs), $out, $machine and $stamp.
echo "== rndmesh: Monte Carlo annealing, thesis schedule (200 anneals x 100 sweeps), one core" >&2
{
  bench_header
  echo "stage,N,anneals,sweeps,T_max,T_min,seconds,trial_moves_per_s,ns_per_move,acceptance"
  for n in 642 2562 10242; do "$bench/bench_spheremesh" anneal $n; done
} | tee "$out/rndmesh_anneal.csv" >&2

echo "== rndmesh: annealing speed by temperature decade (N = 1000, 50 anneals x 100 sweeps each)" >&2
{
  bench_header
  echo "stage,N,anneals,sweeps,T_max,T_min,seconds,trial_moves_per_s,ns_per_move,acceptance"
  for range in "1000 100" "100 10" "10 1" "1 0.1"; do "$bench/bench_spheremesh" anneal 1000 50 100 $range; done
} | tee "$out/rndmesh_anneal_decades.csv" >&2

echo "== rndmesh: spherical Delaunay (CGAL), one core" >&2
{
  bench_header
  echo "stage,N,faces,seconds,points_per_s"
  for n in 1000 10000 100000 1000000; do "$bench/bench_spheremesh" delaunay $n; done
} | tee "$out/rndmesh_delaunay.csv" >&2

echo "== neighbours: Verlet list of 100k particles at phi = 0.64 (cutoff 1, skin 0.1)" >&2
{
  bench_header
  "$bench/bench_neighbours"
} | tee "$out/neighbours.csv" >&2

