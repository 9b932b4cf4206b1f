// How lbflow tells from the environment whether a launcher started it on several ranks
// (lbm/comm/communicator_common.hpp): the size a launcher states, none, a malformed one, and
// a PMIx launcher that states only the rank (the size then comes from MPI itself).
#include "lbm/comm/communicator_common.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

using namespace cmp::lbm::comm_detail;

namespace {
const std::vector<std::string> kLauncherVariables = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK", "PMIX_RANK",
                                                     "SLURM_STEP_NUM_TASKS"};

using Variables = std::vector<std::pair<std::string, std::string>>;

// Sets exactly these launcher variables for the scope, and restores the environment after.
class LauncherEnvironment {
 public:
  explicit LauncherEnvironment(const Variables& set) {
    for (const auto& v : kLauncherVariables) {
      if (const char* s = std::getenv(v.c_str())) saved_.emplace_back(v, s);
      ::unsetenv(v.c_str());
    }
    for (const auto& [k, v] : set) ::setenv(k.c_str(), v.c_str(), 1);
  }
  LauncherEnvironment(const LauncherEnvironment&) = delete;
  LauncherEnvironment& operator=(const LauncherEnvironment&) = delete;
  ~LauncherEnvironment() {
    for (const auto& v : kLauncherVariables) ::unsetenv(v.c_str());
    for (const auto& [k, v] : saved_) ::setenv(k.c_str(), v.c_str(), 1);
  }

 private:
  Variables saved_;
};
}  // namespace

TEST_CASE("launcher environment: no launcher is one process", "[lbm][mpi]") {
  LauncherEnvironment env(Variables{});
  CHECK_FALSE(launched_by_mpi());
  CHECK(launched_size() == 1);
  CHECK_FALSE(has_process_manager());
}

TEST_CASE("launcher environment: the size mpirun or srun states", "[lbm][mpi]") {
  {
    LauncherEnvironment env(Variables{{"OMPI_COMM_WORLD_SIZE", "4"}});
    CHECK(launched_by_mpi());
    CHECK(launched_size() == 4);
    CHECK(has_process_manager());
  }
  {
    LauncherEnvironment env(Variables{{"SLURM_STEP_NUM_TASKS", "2"}});  // srun without an MPI plugin
    CHECK(launched_by_mpi());
    CHECK(launched_size() == 2);
    CHECK_FALSE(has_process_manager());
  }
}

TEST_CASE("launcher environment: a malformed size counts as one process", "[lbm][mpi]") {
  LauncherEnvironment env(Variables{{"PMI_SIZE", "4x"}});
  CHECK(launched_size() == 1);
}

TEST_CASE("launcher environment: a PMIx rank without a size leaves the size to MPI", "[lbm][mpi]") {
  LauncherEnvironment env(Variables{{"PMIX_RANK", "1"}});
  CHECK(launched_by_mpi());
  CHECK(launched_size() == 0);  // unknown: not taken for one process, which would run the whole flow on every rank
  CHECK(has_process_manager());
}
