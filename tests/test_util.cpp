#include "test_util.h"

#include <stdexcept>

#include "bccmis/trace.h"

namespace bccmis::test {

Graph build(const std::string& trace_text) {
  std::string log;
  Graph g = replay<Graph>(parse_trace(trace_text, "<test>"), log);
  if (log.find("refused") != std::string::npos)
    throw std::runtime_error("test setup: an operation was refused:\n" + log);
  return g;
}

std::string decisions(const std::string& trace_text) {
  std::string log;
  replay<Graph>(parse_trace(trace_text, "<test>"), log);
  return log;
}

}  // namespace bccmis::test
