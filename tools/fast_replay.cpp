// bccmis-fast-replay TRACE: replays a trace (spec/formats.md) with
// bccmis::fast::Lattice and prints what `bccmis replay --quiet --check=none`
// prints: the decision log, then the canonical state. The conformance
// protocol of spec/conformance.md, so that
//   bccmis conformance --impl bccmis-fast-replay --traces spec/examples --random 300
// checks the fast implementation against the reference (tests/fast/fast.cmake).
//
// Exit codes: 0 ok; 2 unreadable file or malformed trace (one line on stderr).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "bccmis/fast/lattice.h"
#include "bccmis/io/format.h"
#include "bccmis/trace.h"

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "--help") {
    std::cerr << "usage: bccmis-fast-replay TRACE\n"
                 "Replays TRACE with the fast implementation; prints the decision log and the canonical state.\n";
    return argc == 2 ? 0 : 2;
  }
  const std::string path = argv[1];
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << "bccmis-fast-replay: " << path << ": cannot open for reading"
              << (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()) << "\n";
    return 2;
  }
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const bccmis::Trace trace = bccmis::parse_trace(text.str(), path);
    std::string log;
    const auto g = bccmis::replay<bccmis::fast::Lattice>(trace, log);
    std::cout << log;
    write_canonical_state(std::cout, g);
    std::cout.flush();
    return std::cout ? 0 : 2;
  } catch (const bccmis::ParseError& e) {
    std::cerr << "bccmis-fast-replay: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "bccmis-fast-replay: " << e.what() << "\n";
    return 2;
  }
}
