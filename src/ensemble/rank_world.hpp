#pragma once
// The ranks an ensemble runs on: one process (rank 0 of 1), or the processes `mpirun -n K`
// started (OpenMPI), which then deal the members among themselves and send their results to
// rank 0. MPI is initialised only when the process was started by mpirun (the launcher's
// environment variables are set) and the program was built with MPI (FLOTSAM_MPI); otherwise
// the ensemble runs alone, without touching MPI. Only the thread that made the RankWorld calls
// MPI (MPI_THREAD_FUNNELED): the members' threads never do.
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace flotsam {

/// A rank's progress over its members: done (with those kept from an earlier run), kept,
/// failed, and 1 once all its members are done.
using RankTally = std::array<int, 4>;

class RankWorld {
 public:
  RankWorld();
  ~RankWorld();
  RankWorld(const RankWorld&) = delete;
  RankWorld& operator=(const RankWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool uses_mpi() const { return mpi_; }

  /// Rank 0 receives every rank's `text`, in rank order; the other ranks get an empty list.
  std::vector<std::string> gather(const std::string& text) const;
  /// Every rank receives rank 0's `text`.
  std::string broadcast(const std::string& text) const;
  /// A rank other than 0 sends its tally to rank 0 (a message it never waits on).
  void send_tally(const RankTally& tally) const;
  /// Rank 0: the tallies that arrived since the last call, as (rank, tally), in arrival order.
  std::vector<std::pair<int, RankTally>> receive_tallies() const;
  /// Stops every rank (an error on one rank would otherwise leave the others waiting).
  [[noreturn]] void abort(int code) const;

  /// True when the environment says an MPI launcher started this process.
  static bool launched_by_mpirun();

 private:
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
};

}  // namespace flotsam
