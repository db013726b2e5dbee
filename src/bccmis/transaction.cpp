#include "bccmis/transaction.h"

namespace bccmis {

template class BasicTransaction<Graph>;

}  // namespace bccmis
