#include "pellicle/dist/communicator.hpp"

#include <mpi.h>

#include <cstdlib>

namespace pellicle {

Communicator::Communicator(int& argc, char**& argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm machine;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &machine);
  MPI_Comm_size(machine, &local_size_);
  MPI_Comm_free(&machine);
}

Communicator::~Communicator() {
  MPI_Finalize();
}

void Communicator::sum_in_rank_order(std::vector<double>& values) const {
  const int n = static_cast<int>(values.size());
  std::vector<double> all(static_cast<std::size_t>(n) * size_);
  MPI_Allgather(values.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, MPI_COMM_WORLD);
  for (int i = 0; i < n; ++i) {
    double total = all[i];
    for (int r = 1; r < size_; ++r) total += all[static_cast<std::size_t>(r) * n + i];
    values[i] = total;
  }
}

void Communicator::sum(std::vector<long>& values) const {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_LONG, MPI_SUM,
                MPI_COMM_WORLD);
}

void Communicator::max(std::vector<double>& values) const {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                MPI_COMM_WORLD);
}

double Communicator::max(double value) const {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

double Communicator::min(double value) const {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  return value;
}

void Communicator::exchange(const std::vector<Message>& outgoing,
                            std::vector<Message>& incoming) const {
  constexpr int kTag = 17;
  std::vector<MPI_Request> requests(outgoing.size() + incoming.size());
  std::size_t r = 0;
  for (auto& in : incoming)
    MPI_Irecv(in.values.data(), static_cast<int>(in.values.size()), MPI_DOUBLE, in.rank, kTag,
              MPI_COMM_WORLD, &requests[r++]);
  for (const auto& out : outgoing)
    MPI_Isend(out.values.data(), static_cast<int>(out.values.size()), MPI_DOUBLE, out.rank, kTag,
              MPI_COMM_WORLD, &requests[r++]);
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

namespace {

//! Send each non-empty to_rank[r] and receive from each rank r with counts[r] > 0.
void send_payloads(const Communicator& world, const std::vector<std::vector<double>>& to_rank,
                   const std::vector<int>& receive_counts,
                   std::vector<std::vector<double>>& from_rank) {
  std::vector<Communicator::Message> outgoing, incoming;
  for (int r = 0; r < world.size(); ++r) {
    if (!to_rank[r].empty()) outgoing.push_back({r, to_rank[r]});
    if (receive_counts[r] > 0) incoming.push_back({r, std::vector<double>(receive_counts[r])});
  }
  world.exchange(outgoing, incoming);
  from_rank.assign(world.size(), {});
  for (auto& in : incoming) from_rank[in.rank] = std::move(in.values);
}

}  // namespace

void Communicator::all_to_all(const std::vector<std::vector<double>>& to_rank,
                              std::vector<std::vector<double>>& from_rank) const {
  std::vector<int> send_counts(size_), receive_counts(size_);
  for (int r = 0; r < size_; ++r) send_counts[r] = static_cast<int>(to_rank[r].size());
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  // Then only the ranks that have something to say talk (mostly none, or a neighbour).
  send_payloads(*this, to_rank, receive_counts, from_rank);
}

void Communicator::neighbour_all_to_all(const std::vector<std::vector<double>>& to_rank,
                                        std::vector<std::vector<double>>& from_rank,
                                        const std::vector<int>& neighbours) const {
  std::vector<char> near(size_, 0);
  for (int r : neighbours) near[r] = 1;
  near[rank_] = 1;
  double beyond = 0.0;
  for (int r = 0; r < size_; ++r)
    if (!to_rank[r].empty() && !near[r]) beyond = 1.0;
  if (max(beyond) > 0.0) return all_to_all(to_rank, from_rank);
  std::vector<Message> outgoing, incoming;
  for (int r : neighbours) {
    outgoing.push_back({r, {static_cast<double>(to_rank[r].size())}});
    incoming.push_back({r, std::vector<double>(1)});
  }
  exchange(outgoing, incoming);
  std::vector<int> receive_counts(size_, 0);
  receive_counts[rank_] = static_cast<int>(to_rank[rank_].size());
  for (const auto& in : incoming) receive_counts[in.rank] = static_cast<int>(in.values[0]);
  send_payloads(*this, to_rank, receive_counts, from_rank);
}

std::vector<double> Communicator::all_gather(const std::vector<double>& mine) const {
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(size_), offsets(size_, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < size_; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<std::size_t>(offsets.back()) + counts.back());
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 MPI_COMM_WORLD);
  return all;
}

void Communicator::abort(int exit_code) const {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::abort();  // MPI_Abort does not return
}

}  // namespace pellicle
