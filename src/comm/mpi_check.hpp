// For the sources of src/comm only (it includes mpi.h): a failed MPI call becomes an
// exception naming the call, the same way for the communicator and the exchange.
#pragma once

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace crumple::comm {

inline void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI failure in ") + what);
}

}  // namespace crumple::comm
