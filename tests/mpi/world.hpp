#pragma once
//! The ranks the MPI tests run on (main.cpp).

#include "pellicle/dist/communicator.hpp"

namespace pellicle {
extern Communicator* world;
}  // namespace pellicle
