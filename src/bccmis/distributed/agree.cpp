// spec/distributed.md D6: the ranks agree on the outcome of a stage.
#include <climits>
#include <exception>
#include <string>

#include "bccmis/distributed/ranks.h"

namespace bccmis::distributed {

Agreement agree(int code, MPI_Comm comm) {
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int first = code != 0 ? rank : INT_MAX;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return {};
  Agreement a{first, code};
  MPI_Bcast(&a.code, 1, MPI_INT, first, comm);
  return a;
}

void rethrow_on_every_rank(const std::exception_ptr& failed, const std::string& what, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int first = failed ? rank : INT_MAX;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return;
  if (failed) std::rethrow_exception(failed);
  throw RankFailed(first, what + " failed (spec/distributed.md D6)");
}

}  // namespace bccmis::distributed
