#include "validators.h"

#include <cmath>

namespace bccmis::cli {

/// An integer from `lo` to `hi`; CLI11 prefixes the option's name to the
/// message, which names the value as given: "--max-level: '3.5' is not an
/// integer from 0 to 20".
CLI::Validator integer_in(std::int64_t lo, std::int64_t hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        std::int64_t v = 0;
        return read_whole(text, v) && v >= lo && v <= hi ? std::string()
                                                         : "'" + text + "' is not an integer from " + range;
      },
      "INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

/// A whole number >= 0 (seeds, counts): "--threads: '-1' is not a
/// non-negative integer".
CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t v = 0;
        return read_whole(text, v) ? std::string() : "'" + text + "' is not a non-negative integer";
      },
      "NONNEGATIVE");
}

/// A finite number above zero: "--size: '0' is not a positive finite number".
CLI::Validator positive_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0;
        return read_whole(text, v) && std::isfinite(v) && v > 0 ? std::string()
                                                                : "'" + text + "' is not a positive finite number";
      },
      "POSITIVE");
}

}  // namespace bccmis::cli
