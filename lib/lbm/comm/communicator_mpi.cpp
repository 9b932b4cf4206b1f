// lbm/communicator.hpp on MPI (CMP_MPI=ON). MPI is initialised only when a launcher started the
// process, so `lbflow` alone runs as one process without touching the MPI runtime.
#include "lbm/communicator.hpp"

#include "core/errors.hpp"
#include "lbm/comm/communicator_common.hpp"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <exception>
#include <new>
#include <numeric>
#include <string>

#include <unistd.h>

namespace cmp::lbm {

namespace {
bool g_initialised = false;
bool g_error_agreed = false;  // the last agree() threw (reset by every agree), or past_collectives()
constexpr std::size_t kPiece = std::size_t{1} << 30;  // bytes per message piece (MPI counts are int)

void mpi_check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw ComputationError(std::string("MPI: ") + what + " failed");
}

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> d(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) d[r] = d[r - 1] + counts[r - 1];
  return d;
}
}  // namespace

Communicator Communicator::world() {
  Communicator c;
  // One task (lbflow alone, `mpirun -np 1`, or a study's `srun -n1` job step): no MPI at all.
  if (!comm_detail::launched_by_mpi() || comm_detail::launched_size() == 1) return c;
  if (!comm_detail::has_process_manager())
    throw UsageError("srun started " + std::to_string(comm_detail::launched_size()) +
                     " tasks without an MPI plugin, so each would run the whole flow: use srun --mpi=pmix");
  int done = 0;
  MPI_Initialized(&done);
  if (!done) {
    int provided = 0;
    // Only the main thread calls MPI (OpenMP threads work between the calls).
    mpi_check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    g_initialised = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &c.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &c.size_);
  c.mpi_ = c.size_ > 1;
  return c;
}

void Communicator::finalize() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (g_initialised && !finalized) MPI_Finalize();
}
bool Communicator::launched_by_mpi() { return comm_detail::launched_by_mpi(); }
bool Communicator::built_with_mpi() { return true; }

std::vector<char> Communicator::all_gather_bytes(const std::vector<char>& mine) const {
  if (!mpi_) return mine;
  std::vector<int> counts(static_cast<std::size_t>(size_));
  int n = static_cast<int>(mine.size());
  mpi_check(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  const auto displ = displacements(counts);
  std::vector<char> all(static_cast<std::size_t>(displ.back() + counts.back()));
  mpi_check(MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, MPI_COMM_WORLD),
        "MPI_Allgatherv");
  return all;
}

std::vector<double> Communicator::all_gather(const std::vector<double>& mine) const {
  if (!mpi_) return mine;
  std::vector<int> counts(static_cast<std::size_t>(size_));
  int n = static_cast<int>(mine.size());
  mpi_check(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  const auto displ = displacements(counts);
  std::vector<double> all(static_cast<std::size_t>(displ.back() + counts.back()));
  mpi_check(MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displ.data(), MPI_DOUBLE,
                       MPI_COMM_WORLD),
        "MPI_Allgatherv");
  return all;
}

std::vector<double> Communicator::gather_to_root(const std::vector<double>& mine) const {
  if (!mpi_) return mine;
  // Rank by rank through send/recv: no int overflow of Gatherv's displacements on large fields.
  const int kTag = 7001;
  if (!root()) {
    const long n = static_cast<long>(mine.size());
    send(0, kTag, &n, sizeof n);
    send(0, kTag, mine.data(), mine.size() * sizeof(double));
    return {};
  }
  std::vector<double> all = mine;
  for (int r = 1; r < size_; ++r) {
    long n = 0;
    recv(r, kTag, &n, sizeof n);
    const std::size_t at = all.size();
    all.resize(at + static_cast<std::size_t>(n));
    recv(r, kTag, all.data() + at, static_cast<std::size_t>(n) * sizeof(double));
  }
  return all;
}

long Communicator::sum(long v) const {
  if (!mpi_) return v;
  long out = 0;
  mpi_check(MPI_Allreduce(&v, &out, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

int Communicator::max(int v) const {
  if (!mpi_) return v;
  int out = 0;
  mpi_check(MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

bool Communicator::broadcast_flag(bool v) const {
  if (!mpi_) return v;
  int x = v ? 1 : 0;
  mpi_check(MPI_Bcast(&x, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return x != 0;
}

void Communicator::send(int to, int tag, const void* data, std::size_t bytes) const {
  const char* p = static_cast<const char*>(data);
  do {
    const std::size_t n = std::min(bytes, kPiece);
    mpi_check(MPI_Send(p, static_cast<int>(n), MPI_BYTE, to, tag, MPI_COMM_WORLD), "MPI_Send");
    p += n;
    bytes -= n;
  } while (bytes > 0);
}

void Communicator::recv(int from, int tag, void* data, std::size_t bytes) const {
  char* p = static_cast<char*>(data);
  do {
    const std::size_t n = std::min(bytes, kPiece);
    mpi_check(MPI_Recv(p, static_cast<int>(n), MPI_BYTE, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    p += n;
    bytes -= n;
  } while (bytes > 0);
}

void Communicator::exchange(const std::vector<Transfer>& transfers, int tag) const {
  if (transfers.empty()) return;
  std::vector<MPI_Request> requests;
  requests.reserve(2 * transfers.size());
  for (const Transfer& t : transfers) {
    if (t.peer == rank_) {  // one rank on both sides of a periodic axis
      std::copy_n(static_cast<const char*>(t.send), t.send_bytes, static_cast<char*>(t.recv));
      continue;
    }
    requests.emplace_back();
    mpi_check(MPI_Irecv(t.recv, static_cast<int>(t.recv_bytes), MPI_BYTE, t.peer, tag, MPI_COMM_WORLD, &requests.back()),
          "MPI_Irecv");
  }
  for (const Transfer& t : transfers) {
    if (t.peer == rank_) continue;
    requests.emplace_back();
    mpi_check(MPI_Isend(t.send, static_cast<int>(t.send_bytes), MPI_BYTE, t.peer, tag, MPI_COMM_WORLD,
                    &requests.back()),
          "MPI_Isend");
  }
  if (requests.empty()) return;  // (one process: MPI may not even be initialised)
  mpi_check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
}

void Communicator::agree(const std::function<void()>& body) const {
  if (!mpi_) return body();
  g_error_agreed = false;
  // kind: 0 ok, 1 bad input (exit 2), 2 computation failed (exit 1).
  int kind = 0;
  std::string message;
  std::exception_ptr error;
  try {
    body();
  } catch (const std::exception& e) {
    const FailureReport report = failure_report(e);
    kind = report.bad_input ? 1 : 2, message = report.message, error = std::current_exception();
  }
  // The lowest failing rank (size_ when none).
  const int first = -max(kind ? -rank_ : -size_);
  if (first == size_) return;
  int k = kind;
  int length = static_cast<int>(message.size());
  mpi_check(MPI_Bcast(&k, 1, MPI_INT, first, MPI_COMM_WORLD), "MPI_Bcast");
  mpi_check(MPI_Bcast(&length, 1, MPI_INT, first, MPI_COMM_WORLD), "MPI_Bcast");
  message.resize(static_cast<std::size_t>(length));
  mpi_check(MPI_Bcast(message.data(), length, MPI_CHAR, first, MPI_COMM_WORLD), "MPI_Bcast");
  g_error_agreed = true;
  // Rank 0 failed: its own error, as on one process (the others print nothing).
  if (first == 0 && rank_ == 0) std::rethrow_exception(error);
  if (first != 0) message = "rank " + std::to_string(first) + ": " + message;
  if (k == 1) throw UsageError(message);
  throw ComputationError(message);
}

bool Communicator::error_agreed() { return g_error_agreed; }
void Communicator::past_collectives() const { g_error_agreed = true; }

void Communicator::abort_all(const std::string& message, int status, int error_fd) const {
  if (!mpi_) return;
  const std::string line = "lbflow: rank " + std::to_string(rank_) + ": " + message + "\n";
  if (error_fd >= 0) [[maybe_unused]] const auto written = ::write(error_fd, line.data(), line.size());
  MPI_Abort(MPI_COMM_WORLD, status);
}

}  // namespace cmp::lbm
