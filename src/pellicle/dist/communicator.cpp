#include "pellicle/dist/communicator.hpp"

#include <mpi.h>

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

}  // namespace pellicle
