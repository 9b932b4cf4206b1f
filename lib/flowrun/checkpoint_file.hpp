#pragma once
// lbflow's checkpoint file: what `lbflow --resume FILE` needs to continue a run to exactly the
// result of an uninterrupted one. The container of io/checkpoint_file.hpp: a text header
// naming the run (the command-line arguments that define it, so `--resume FILE` alone repeats
// them), then the solver's own binary state
// (lbm::FlowSolver::save: populations, step count, fingerprint of lattice and settings, and
// the convergence checks so far):
//   lbflow checkpoint 2
//   args <n>
//   <length> <argument bytes>        (n lines)
//   state fnv1a64
//   <FlowSolver::save bytes>
//   \nfnv1a64 <16 hex digits>\n       (checksum of the state: a damaged file is refused, exit 2)
#include "lbm/flow_solver.hpp"

#include <string>
#include <vector>

namespace cmp::flowrun {

// Writes the checkpoint atomically (io::AtomicOutput: a run killed while writing leaves the
// previous checkpoint intact). Throws cmp::InputError(path, 0, ...) when it cannot be written.
// On several ranks (comm): collective; rank 0 writes the file, the others send it their state.
void write_checkpoint(const std::string& path, const std::vector<std::string>& args, const lbm::FlowSolver& solver,
                      const std::vector<lbm::FlowObservables>& history, const lbm::Communicator& comm = {});

// The arguments a checkpoint was written with. Throws cmp::InputError(path, line, ...) when the
// file is missing or is not an lbflow checkpoint.
std::vector<std::string> read_checkpoint_args(const std::string& path);

// Loads the state into solver and returns the checks so far. Throws cmp::InputError(path, 0,
// ...) as read_checkpoint_args, and when the state belongs to another run (its fingerprint
// differs from solver's: another input, refinement, collision model, tau, drive, ...) or is
// truncated; the solver is then unchanged.
// Every rank reads the file and keeps its own nodes (a run saved on k ranks resumes on any number).
std::vector<lbm::FlowObservables> load_checkpoint(const std::string& path, lbm::FlowSolver& solver,
                                                  const lbm::Communicator& comm = {});

}  // namespace cmp::flowrun
