// lbm/communicator.hpp without MPI (CMP_MPI=OFF): one process; every collective is the identity.
#include "lbm/communicator.hpp"

#include "core/errors.hpp"
#include "lbm/comm/communicator_common.hpp"

#include <cstring>
#include <stdexcept>

namespace cmp::lbm {

Communicator Communicator::world() {
  if (comm_detail::launched_size() > 1)
    throw UsageError("this lbflow was built without MPI (cmake -DCMP_MPI=ON): started on " +
                     std::to_string(comm_detail::launched_size()) + " ranks, each would run the whole flow");
  return Communicator();
}
void Communicator::finalize() {}
bool Communicator::launched_by_mpi() { return comm_detail::launched_by_mpi(); }
bool Communicator::built_with_mpi() { return false; }

std::vector<double> Communicator::all_gather(const std::vector<double>& mine) const { return mine; }
std::vector<char> Communicator::all_gather_bytes(const std::vector<char>& mine) const { return mine; }
std::vector<double> Communicator::gather_to_root(const std::vector<double>& mine) const { return mine; }
long Communicator::sum(long v) const { return v; }
int Communicator::max(int v) const { return v; }
bool Communicator::broadcast_flag(bool v) const { return v; }
void Communicator::send(int, int, const void*, std::size_t) const {
  throw std::logic_error("Communicator::send on one process");
}
void Communicator::recv(int, int, void*, std::size_t) const {
  throw std::logic_error("Communicator::recv on one process");
}
void Communicator::exchange(const std::vector<Transfer>& transfers, int) const {
  for (const Transfer& t : transfers) std::memcpy(t.recv, t.send, t.send_bytes);  // peer is this process
}
void Communicator::agree(const std::function<void()>& body) const { body(); }
bool Communicator::error_agreed() { return true; }
void Communicator::past_collectives() const {}
void Communicator::abort_all(const std::string&, int, int) const {}

}  // namespace cmp::lbm
