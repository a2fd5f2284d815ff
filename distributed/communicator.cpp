#include "distributed/communicator.hpp"

#include <cstdlib>
#include <exception>

#include <mpi.h>

#include "base/error.hpp"

namespace cellproj {

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

MpiSession::MpiSession(int* argc, char*** argv) {
  if (!launched_by_mpi()) return;
  // The readers run in a forked child (io/isolated_read): over shared memory and TCP that is safe,
  // and OpenMPI's warning about it would only alarm.
  setenv("OMPI_MCA_mpi_warn_on_fork", "0", 0);
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
}

MpiSession::~MpiSession() {
  if (initialised_) MPI_Finalize();
}

Communicator Communicator::world() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  Communicator c;
  if (!initialised || finalised) return c;
  c.mpi = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &c.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &c.size);
  return c;
}

void agree(const Communicator& comm, const std::function<void()>& step) {
  if (!comm.mpi) return step();  // one process: its own error, as it is
  std::string error;
  int severity = 0;  // 1 bad input, 2 a resource the machine lacks, 3 anything else (the CLI's exit codes)
  try {
    step();
  } catch (const InputError& e) {
    error = e.what(), severity = 1;
  } catch (const ResourceError& e) {
    error = e.what(), severity = 2;
  } catch (const std::exception& e) {
    error = e.what(), severity = 3;
  }
  if (severity > 0 && error.empty()) error = "failed";
  int worst = 0;
  MPI_Allreduce(&severity, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (worst == 0) return;
  int mine = static_cast<int>(error.size());
  std::vector<int> lengths(comm.size), offsets(comm.size, 0);
  MPI_Allgather(&mine, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < comm.size; ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
  std::string all(static_cast<std::size_t>(offsets.back() + lengths.back()), '\0');
  MPI_Allgatherv(error.data(), mine, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, MPI_COMM_WORLD);
  std::string message;
  for (int r = 0; r < comm.size; ++r)
    if (lengths[r] > 0)
      message += (message.empty() ? "" : "\n  ") + std::string("rank ") + std::to_string(r) + ": " +
                 all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r]));
  if (worst == 1) throw CollectiveError(message);
  if (worst == 2) throw ResourceError(message);
  throw InternalError(message);
}

std::vector<double> gather_to_root(const Communicator& comm, const std::vector<double>& values) {
  if (!comm.mpi) return values;
  std::vector<double> all(comm.rank == 0 ? values.size() * comm.size : 0);
  MPI_Gather(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(), static_cast<int>(values.size()),
             MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return all;
}

}  // namespace cellproj
