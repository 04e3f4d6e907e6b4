#pragma once
/// \file mpi_world.hpp
/// \brief MPI for a sweep, started only when the program was launched by an MPI launcher
/// (mpirun/mpiexec of Open MPI or MPICH, or Slurm's srun: their environment variables
/// say so); without one, nothing of MPI is touched and the sweep runs as a plain
/// threaded program. Threads may call MPI one at a time (MPI_THREAD_SERIALIZED).

namespace flapsim::sweep {

/// \brief True if the environment shows an MPI launcher started this process.
bool launched_by_mpi();

class MpiWorld {
 public:
  /// Initialises MPI if launched_by_mpi(), else stands for a world of one rank.
  /// \throws std::runtime_error if MPI cannot be initialised
  MpiWorld();
  ~MpiWorld();  ///< MPI_Finalize if it was initialised
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  bool active() const { return active_; }  ///< MPI initialised here
  int rank() const { return rank_; }
  int size() const { return size_; }
  int ranks_on_host() const { return local_size_; }        ///< ranks sharing this machine
  bool serialized_threads() const { return serialized_; }  ///< threads may call MPI

 private:
  bool active_ = false;
  bool serialized_ = true;
  int rank_ = 0, size_ = 1, local_size_ = 1;
};

}  // namespace flapsim::sweep
