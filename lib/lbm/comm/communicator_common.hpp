#pragma once
// Parts both communicator implementations share (internal to lib/lbm).
#include "io/parse_number.hpp"

#include <cstdlib>

namespace cmp::lbm::comm_detail {

// The environment a launcher sets: OpenMPI's mpirun, PMI(x) (srun, hydra), Slurm's srun.
inline bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"})
    if (std::getenv(v)) return true;
  return false;
}

// The number of ranks the launcher started: 1 when no launcher says, or one says no whole
// number; 0 (unknown: MPI_Comm_size tells) when only a process manager's rank is set (a PMIx
// launcher that sets PMIX_RANK but no size).
inline int launched_size() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"})
    if (const char* s = std::getenv(v)) {
      long long n = 0;
      return io::try_parse_integer(s, n) && n >= 1 && n <= 1 << 20 ? static_cast<int>(n) : 1;
    }
  for (const char* v : {"PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v)) return 0;
  return 1;
}

// Whether a process manager the MPI library can talk to started this process (mpirun, or
// srun with an MPI plugin); srun alone sets only SLURM_* variables.
inline bool has_process_manager() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace cmp::lbm::comm_detail
