#include "pipeline/app/sweep/mpi_world.hpp"

#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace flapsim::sweep {

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

namespace {

// Slurm's srun without an MPI plug-in starts N copies that each see a world of one:
// they would all run every case. Refuse that.
void check_not_split(int size) {
  const char* tasks = std::getenv("SLURM_STEP_NUM_TASKS");
  if (tasks && std::atoi(tasks) > 1 && size == 1)
    throw std::runtime_error(std::string("srun started ") + tasks +
                             " tasks but MPI sees one: start them with srun --mpi=pmix (or pmi2), or mpirun");
}

}  // namespace

MpiWorld::MpiWorld() {
  if (!launched_by_mpi()) {
    check_not_split(1);
    return;
  }
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  active_ = true;
  serialized_ = provided >= MPI_THREAD_SERIALIZED;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm host;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &host);
  MPI_Comm_size(host, &local_size_);
  MPI_Comm_free(&host);
  if (size_ == 1 && std::getenv("SLURM_STEP_NUM_TASKS")) {
    try {
      check_not_split(size_);
    } catch (...) {
      MPI_Finalize();
      throw;
    }
  }
}

MpiWorld::~MpiWorld() {
  if (active_) MPI_Finalize();
}

}  // namespace flapsim::sweep
