#include "flowrun/checkpoint_file.hpp"

#include "io/atomic_output.hpp"
#include "io/checkpoint_file.hpp"

#include <fstream>
#include <optional>
#include <ostream>

namespace cmp::flowrun {

namespace {
// 2: a checksum of the state follows it (io::CheckpointOutput); 1 had none.
constexpr const char* kMagic = "lbflow checkpoint 2";
constexpr const char* kWhat = "an lbflow checkpoint";
}  // namespace

void write_checkpoint(const std::string& path, const std::vector<std::string>& args, const lbm::FlowSolver& solver,
                      const std::vector<lbm::FlowObservables>& history, const lbm::Communicator& comm) {
  // A file rank 0 cannot open or complete stops every rank (no rank waits on the others).
  std::optional<io::CheckpointOutput> out;
  comm.agree([&] {
    if (comm.root()) out.emplace(path, kMagic, args);
  });
  std::ostream none(nullptr);
  solver.save(out ? out->stream() : none, history);
  comm.agree([&] {
    if (out) out->commit();
  });
}

std::vector<std::string> read_checkpoint_args(const std::string& path) {
  auto in = io::open_checkpoint(path);
  return io::read_checkpoint_header(in, path, kMagic, kWhat, true);
}

std::vector<lbm::FlowObservables> load_checkpoint(const std::string& path, lbm::FlowSolver& solver,
                                                  const lbm::Communicator& comm) {
  std::ifstream in;
  comm.agree([&] {
    in = io::open_checkpoint(path);
    io::read_checkpoint_header(in, path, kMagic, kWhat, true);
  });
  return solver.load(in, path);  // agrees on its own reading; its halo fill is collective
}

}  // namespace cmp::flowrun
