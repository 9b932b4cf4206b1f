#include "flowrun/checkpoint_file.hpp"

#include "io/atomic_output.hpp"
#include "io/checkpoint_file.hpp"

namespace cmp::flowrun {

namespace {
constexpr const char* kMagic = "lbflow checkpoint 1";
constexpr const char* kWhat = "an lbflow checkpoint";
}  // namespace

void write_checkpoint(const std::string& path, const std::vector<std::string>& args, const lbm::FlowSolver& solver,
                      const std::vector<lbm::FlowObservables>& history) {
  io::AtomicOutput out(path);
  auto& s = out.stream();
  io::write_checkpoint_header(s, kMagic, args);
  solver.save(s, history);
  out.commit();
}

std::vector<std::string> read_checkpoint_args(const std::string& path) {
  auto in = io::open_checkpoint(path);
  return io::read_checkpoint_header(in, path, kMagic, kWhat);
}

std::vector<lbm::FlowObservables> load_checkpoint(const std::string& path, lbm::FlowSolver& solver) {
  auto in = io::open_checkpoint(path);
  io::read_checkpoint_header(in, path, kMagic, kWhat);
  return solver.load(in, path);
}

}  // namespace cmp::flowrun
