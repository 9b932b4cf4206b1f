#include "flowrun/checkpoint_file.hpp"

#include "io/atomic_output.hpp"
#include "io/checkpoint_file.hpp"

namespace cmp::flowrun {

namespace {
// 2: a checksum of the state follows it (io::CheckpointOutput); 1 had none.
constexpr const char* kMagic = "lbflow checkpoint 2";
constexpr const char* kWhat = "an lbflow checkpoint";
}  // namespace

void write_checkpoint(const std::string& path, const std::vector<std::string>& args, const lbm::FlowSolver& solver,
                      const std::vector<lbm::FlowObservables>& history) {
  io::CheckpointOutput out(path, kMagic, args);
  solver.save(out.stream(), history);
  out.commit();
}

std::vector<std::string> read_checkpoint_args(const std::string& path) {
  auto in = io::open_checkpoint(path);
  return io::read_checkpoint_header(in, path, kMagic, kWhat, true);
}

std::vector<lbm::FlowObservables> load_checkpoint(const std::string& path, lbm::FlowSolver& solver) {
  auto in = io::open_checkpoint(path);
  io::read_checkpoint_header(in, path, kMagic, kWhat, true);
  return solver.load(in, path);
}

}  // namespace cmp::flowrun
