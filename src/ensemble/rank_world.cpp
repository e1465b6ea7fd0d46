#include "ensemble/rank_world.hpp"

#include <cstdlib>

#if FLOTSAM_MPI
#include <mpi.h>
#endif

namespace flotsam {

bool RankWorld::launched_by_mpirun() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(variable) != nullptr) return true;
  return false;
}

#if FLOTSAM_MPI

RankWorld::RankWorld() {
  if (!launched_by_mpirun()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  int provided = 0;
  if (!initialized) MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

RankWorld::~RankWorld() {
  if (mpi_) MPI_Finalize();
}

std::vector<std::string> RankWorld::gather(const std::string& text) const {
  if (!mpi_) return {text};
  // Sizes first, then the texts one after the other (MPI_Gatherv).
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets(lengths.size(), 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    offsets[r] = total;
    total += lengths[r];
  }
  std::string all(rank_ == 0 ? static_cast<std::size_t>(total) : 0, '\0');
  MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, MPI_COMM_WORLD);
  if (rank_ != 0) return {};
  std::vector<std::string> texts;
  for (std::size_t r = 0; r < lengths.size(); ++r)
    texts.push_back(
        all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
  return texts;
}

std::string RankWorld::broadcast(const std::string& text) const {
  if (!mpi_) return text;
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string received = rank_ == 0 ? text : std::string(static_cast<std::size_t>(length), '\0');
  MPI_Bcast(received.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  return received;
}

namespace {
constexpr int tally_tag = 17;  // the progress messages'
}  // namespace

void RankWorld::send_tally(const RankTally& tally) const {
  if (!mpi_ || rank_ == 0) return;
  // A few bytes: sent eagerly, so the send returns at once; rank 0 receives every one before the
  // gather (it waits for each rank's last tally).
  MPI_Send(tally.data(), static_cast<int>(tally.size()), MPI_INT, 0, tally_tag, MPI_COMM_WORLD);
}

std::vector<std::pair<int, RankTally>> RankWorld::receive_tallies() const {
  std::vector<std::pair<int, RankTally>> received;
  if (!mpi_ || rank_ != 0) return received;
  for (;;) {
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tally_tag, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) return received;
    RankTally tally{};
    MPI_Recv(tally.data(), static_cast<int>(tally.size()), MPI_INT, status.MPI_SOURCE, tally_tag,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    received.emplace_back(status.MPI_SOURCE, tally);
  }
}

void RankWorld::abort(int code) const {
  if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

#else

RankWorld::RankWorld() = default;
RankWorld::~RankWorld() = default;
std::vector<std::string> RankWorld::gather(const std::string& text) const {
  return {text};
}
std::string RankWorld::broadcast(const std::string& text) const {
  return text;
}
void RankWorld::send_tally(const RankTally& /*tally*/) const {}
std::vector<std::pair<int, RankTally>> RankWorld::receive_tallies() const {
  return {};
}
void RankWorld::abort(int code) const {
  std::exit(code);
}

#endif

}  // namespace flotsam
