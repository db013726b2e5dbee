// bccmis CLI: what heightfield.cpp and animate.cpp share: option checks,
// the checker with the corner rule, and the statistics record.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/apps/image.h"
#include "bccmis/graph.h"
#include "io.h"

namespace bccmis::cli {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// `v` printed with the printf format `f`.
std::string fmt(double v, const char* f = "%.6g");

/// Throws InputError(message) unless ok.
inline void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

/// The message when two outputs are '-'.
inline constexpr const char* kOneStdout =
    "at most one output can be '-' (standard output); the statistics go there by default, "
    "give them a file with --stats FILE";

/// W and H in 1..1024, L in 0..24; `what` names the source in the message.
void check_lattice_limits(const LatticeSize& s, const std::string& what);

/// "edge" or "corner"; InputError otherwise.
Balance balance_option(const std::string& text);

/// The corner rule's violation as one line, or empty.
std::optional<std::string> corner_violation(const Graph& g);

/// The checker, and with corner balance the corner rule; CheckFailure
/// ("invariant violated WHEN: ...") on a violation.
void run_check(const Graph& g, Balance balance, const std::string& when);

/// Cells per level as text ("0:4 1:12") and as a JSON object (into `json`).
std::string levels_text(const std::map<int, std::size_t>& per_level, std::string& json);
std::string levels_text(const Graph& g, std::string& json);

/// Runs `body`, turning the apps library's errors on bad input (a bad
/// image, lattice size or setting) into InputError.
template <class Body>
int translating_app_errors(Body&& body) {
  try {
    return body();
  } catch (const ImageError& e) {
    throw InputError(e.what());
  } catch (const LatticeError& e) {
    throw InputError(e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

/// Ordered name/value statistics printed as `name value` lines or one JSON object.
class Record {
 public:
  void add(const std::string& name, const std::string& text, bool quoted);
  void add(const std::string& name, std::int64_t v) { add(name, std::to_string(v), false); }
  void add(const std::string& name, double v);
  void add(const std::string& name, const std::string& s) { add(name, s, true); }
  void add(const std::string& name, const char* s) { add(name, std::string(s), true); }
  void add_raw_json(const std::string& name, const std::string& json, const std::string& text);
  std::string text() const;
  std::string json() const;

 private:
  struct Item {
    std::string name, text;
    bool quoted = false;
    std::string json;
  };
  std::vector<Item> items_;
};

}  // namespace bccmis::cli
