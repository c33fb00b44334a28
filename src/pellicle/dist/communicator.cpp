#include "pellicle/dist/communicator.hpp"

#include <mpi.h>

#include <cstdlib>

namespace pellicle {

Communicator::Communicator(int& argc, char**& argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
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

void Communicator::all_to_all(const std::vector<std::vector<double>>& to_rank,
                              std::vector<std::vector<double>>& from_rank) const {
  std::vector<int> send_counts(size_), receive_counts(size_), send_offsets(size_),
      receive_offsets(size_);
  std::vector<double> send;
  for (int r = 0; r < size_; ++r) {
    send_counts[r] = static_cast<int>(to_rank[r].size());
    send_offsets[r] = static_cast<int>(send.size());
    send.insert(send.end(), to_rank[r].begin(), to_rank[r].end());
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < size_; ++r) receive_offsets[r] = total, total += receive_counts[r];
  std::vector<double> received(total);
  MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_DOUBLE, received.data(),
                receive_counts.data(), receive_offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  from_rank.assign(size_, {});
  for (int r = 0; r < size_; ++r)
    from_rank[r].assign(received.begin() + receive_offsets[r],
                        received.begin() + receive_offsets[r] + receive_counts[r]);
}

void Communicator::abort(int exit_code) const {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::abort();  // MPI_Abort does not return
}

}  // namespace pellicle
