// bccmis CLI: the checks of option values that several subcommands share
// (cli.cpp, stuff_command_line.cpp); they include CLI11.
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdint>
#include <string>

namespace bccmis::cli {

/// Whether all of `text` reads as one number (std::from_chars: no sign for
/// an unsigned type, no leading '+' or white space).
template <class Number>
bool read_whole(const std::string& text, Number& value) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && ptr == text.data() + text.size();
}

/// An integer from `lo` to `hi`; CLI11 prefixes the option's name to the
/// message, which names the value as given: "--max-level: '3.5' is not an
/// integer from 0 to 20".
CLI::Validator integer_in(std::int64_t lo, std::int64_t hi);

/// A whole number >= 0 (seeds, counts): "--threads: '-1' is not a
/// non-negative integer".
CLI::Validator non_negative_integer();

/// A finite number above zero: "--size: '0' is not a positive finite number".
CLI::Validator positive_finite();

}  // namespace bccmis::cli
