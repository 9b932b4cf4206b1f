#pragma once
// The processes one flow runs on (lbm/flow_solver.hpp's slab decomposition): MPI_COMM_WORLD
// when lbflow is started by mpirun or srun on a build with MPI (CMake option CMP_MPI), else a
// single process. Two implementations, one linked: lbm/comm/communicator_mpi.cpp and
// lbm/comm/communicator_serial.cpp. Reductions never combine numbers in MPI's own order: the
// ranks' values are gathered in rank order and every rank adds them in that order itself,
// so a sum comes out with the same bits on any number of ranks (the callers cut their sums
// at slab boundaries, which do not move with the rank count).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cmp::lbm {

class Communicator {
 public:
  // One process, no MPI.
  Communicator() = default;
  // MPI_COMM_WORLD, initialised on the first call, when a launcher started this process
  // (launched_by_mpi()) with more than one task; else one process (MPI untouched). srun
  // with several tasks but no MPI plugin (no PMI variables) throws cmp::UsageError. A build without MPI started by a launcher on more
  // than one rank throws cmp::UsageError (every rank would run the whole flow).
  static Communicator world();
  // Finalises MPI if world() initialised it (call once, at the end of main).
  static void finalize();
  // Whether mpirun or srun started this process (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK,
  // SLURM_STEP_NUM_TASKS): plain `lbflow` then needs no MPI runtime at all.
  static bool launched_by_mpi();
  static bool built_with_mpi();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  // Every rank's values concatenated in rank order, on every rank.
  std::vector<double> all_gather(const std::vector<double>& mine) const;
  std::vector<char> all_gather_bytes(const std::vector<char>& mine) const;
  // Every rank's values concatenated in rank order on rank 0 (empty elsewhere).
  std::vector<double> gather_to_root(const std::vector<double>& mine) const;
  long sum(long v) const;  // integers: exact in any order
  int max(int v) const;
  bool broadcast_flag(bool v) const;  // rank 0's value on every rank
  // Point to point (blocking), any size (cut into pieces below MPI's int counts).
  void send(int to, int tag, const void* data, std::size_t bytes) const;
  void recv(int from, int tag, void* data, std::size_t bytes) const;
  // Non-blocking exchange with a few peers: each Transfer sends `send` to `peer` and receives
  // `recv` from it (sizes known to both sides), then waits for all.
  struct Transfer {
    int peer;
    const void* send;
    std::size_t send_bytes;
    void* recv;
    std::size_t recv_bytes;
  };
  void exchange(const std::vector<Transfer>& transfers, int tag) const;

  // Runs body on every rank; if it throws on any rank, every rank throws the same error: the
  // lowest failing rank's, its message prefixed "rank R: " when rank 0 itself did not fail
  // (an error every rank meets, as bad input, reads as on one process). Lets a rank that cannot
  // allocate its share stop all of them, one message, the same exit status everywhere.
  void agree(const std::function<void()>& body) const;
  // Whether the error this rank is leaving with strands no other rank: thrown by agree() (so by
  // every rank together), or after past_collectives(). Any other error after the ranks started
  // talking may leave the others waiting in a collective (a rank 0 that cannot gather the VTK
  // field, an output that fails on rank 0).
  static bool error_agreed();
  // Says that this rank makes no more collective calls in this run but main's status reduction:
  // an error from here on is reported as usual.
  void past_collectives() const;
  // For such an error: writes "lbflow: rank R: message" to `error_fd` (this rank's real standard
  // error) and ends every rank at once with `status` (MPI_Abort). On one process: returns.
  void abort_all(const std::string& message, int status, int error_fd) const;

 private:
  int rank_ = 0, size_ = 1;
  bool mpi_ = false;
};

}  // namespace cmp::lbm
