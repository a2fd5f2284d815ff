#pragma once
// The processes of a distributed render: MPI's world when the command was launched by mpirun (or
// srun), else one process and no MPI at all (the single-machine path of the same binary).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "base/error.hpp"

namespace cellproj {

// What agree() throws on every rank when any rank failed: the failing ranks' messages, one per line.
class CollectiveError : public InputError {
 public:
  using InputError::InputError;
};

// Whether this process was started by an MPI launcher (its environment says so).
bool launched_by_mpi();

// MPI initialised for the life of the object when launched_by_mpi(), else nothing; one per process,
// made in main() before anything else.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool initialised_ = false;
};

// A rank's view of the world (size 1 and no MPI calls without MPI).
struct Communicator {
  int rank = 0, size = 1;
  bool mpi = false;
  static Communicator world();  // MPI_COMM_WORLD if MPI is initialised, else the single process
};

// Runs `step` on every rank and agrees on its outcome, so that no rank waits forever for one that
// failed: if any rank threw, every rank throws one error whose message lists each failing rank's
// ("rank 2: bricks/brick_0002.vtu: ..."), of the gravest class thrown: CollectiveError (bad
// input), ResourceError, or InternalError. Without MPI the step's own error passes as it is.
void agree(const Communicator& comm, const std::function<void()>& step);

// Bytes exchanged and seconds spent in the last collective.
struct TrafficStats {
  std::uint64_t bytes_sent = 0, bytes_received = 0;
  double seconds = 0.0;
};

// Every rank's `values` gathered on rank 0 (rank-major); other ranks get an empty vector.
std::vector<double> gather_to_root(const Communicator& comm, const std::vector<double>& values);

}  // namespace cellproj
