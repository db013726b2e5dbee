// fuzz_conformance: another implementation's output is untrusted input to the
// conformance harness (compare_run), the viewer's side panel
// (implementation_side, `bccmis view --from-log`) and the page (view_trace).
//
// Input layout (every byte string is a valid program):
//   byte 0      the trace: random_trace(seed b0, at most 12 operations), the
//               harness's own generator
//   byte 1      the run's status: b1 % 8 == 0..4 exit 0, 5 exit status b1 / 8,
//               6 killed by signal 1 + b1 / 8 % 31, 7 timed out
//   byte 2      how the rest becomes the implementation's stdout:
//                 even: the rest, as it is
//                 odd:  the reference's own output with a splice: bytes 3-4
//                       an offset into it (little endian, modulo its length
//                       + 1), byte 5 how many bytes to drop there, the rest
//                       inserted (near misses: one wrong digit, a missing
//                       line, a truncated state)
//
// Checks:
//   - compare_run never throws, and it reports agreement exactly when the
//     status is clean and the output is the reference's byte for byte
//     (spec/conformance.md: decisions and canonical state, exactly);
//   - implementation_side (the viewer's --from-log) never throws and gives a
//     side exactly when compare_run, on the output completed with the
//     reference's state when it has none, reports a disagreement; its step is
//     within the trace;
//   - view_trace with that side never throws and writes a whole page.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <random>
#include <string>
#include <string_view>

#include "bccmis/io/format.h"
#include "bccmis/oracle/conformance.h"
#include "bccmis/oracle/view.h"
#include "bccmis/trace.h"
#include "fuzz_util.h"
#include "testing/byte_program.h"

namespace {

using namespace bccmis;

constexpr std::string_view kTarget = "fuzz_conformance";

template <class F>
auto guarded(const Trace& trace, std::string_view what, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::exception& e) {
    fuzz::fail(kTarget, std::string(what) + " threw: " + e.what(), &trace);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  testing::Bytes in(data, size);
  std::mt19937_64 rng(in.next());
  const Trace trace = random_trace(rng, 12);
  const std::string reference = reference_output(trace);

  ImplRun run;
  const std::uint8_t status = in.next();
  switch (status % 8) {
    case 5: run.exit_code = status / 8; break;
    case 6: run.signal = 1 + status / 8 % 31; break;
    case 7: run.timed_out = true; break;
    default: break;
  }
  const bool clean = !run.timed_out && run.signal == 0 && run.exit_code == 0;

  const std::uint8_t mode = in.next();
  std::string rest;
  if ((mode & 1) == 0) {
    while (!in.empty()) rest += static_cast<char>(in.next());
    run.out = rest;
  } else {
    std::size_t at = in.next();
    at |= std::size_t{in.next()} << 8;
    at %= reference.size() + 1;
    const std::size_t drop = in.next();
    while (!in.empty()) rest += static_cast<char>(in.next());
    run.out = reference.substr(0, at) + rest + reference.substr(std::min(reference.size(), at + drop));
  }

  const std::string verdict = guarded(trace, "compare_run", [&] { return compare_run(trace, run); });
  const bool exact = clean && run.out == reference;
  if (verdict.empty() != exact)
    fuzz::fail(kTarget,
               exact ? "compare_run reports a difference on the reference's own output: " + verdict
                     : "compare_run reports agreement on an output that differs from the reference's",
               &trace);

  // The viewer's --from-log: a log without a state is completed with the
  // reference's state, so only its decisions count.
  ImplRun completed = run;
  if (run.out.find("bccmis-state ") == std::string::npos) {
    std::string log;
    completed.out += canonical_state(replay<Graph>(trace, log));
  }
  const std::string completed_verdict = guarded(trace, "compare_run", [&] { return compare_run(trace, completed); });
  const std::optional<ViewSide> side =
      guarded(trace, "implementation_side", [&] { return implementation_side(trace, run, {}, false); });
  if (side.has_value() == completed_verdict.empty())
    fuzz::fail(kTarget,
               side ? "implementation_side shows a disagreement where there is none"
                    : "implementation_side misses the disagreement: " + completed_verdict,
               &trace);
  if (side && side->step > trace.commands.size())
    fuzz::fail(kTarget, "implementation_side puts the disagreement after the last step", &trace);

  ViewOptions options;
  options.side = side;
  if (side) options.open_step = side->step;
  const ViewResult page = guarded(trace, "view_trace", [&] { return view_trace(trace, options); });
  if (page.html.rfind("<!DOCTYPE html>", 0) != 0 || page.html.find("</html>") == std::string::npos)
    fuzz::fail(kTarget, "view_trace wrote an incomplete page", &trace);
  return 0;
}
