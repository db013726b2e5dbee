#include "app_support.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"

namespace bccmis::cli {

namespace {
constexpr std::int64_t kMaxLatticeSide = 1024;  // W and H
constexpr int kMaxLevel = 24;
}  // namespace

std::string fmt(double v, const char* f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

void check_lattice_limits(const LatticeSize& s, const std::string& what) {
  require(s.W >= 1 && s.W <= kMaxLatticeSide && s.H >= 1 && s.H <= kMaxLatticeSide,
          what + ": lattice " + std::to_string(s.W) + "x" + std::to_string(s.H) + " is out of range 1.." +
              std::to_string(kMaxLatticeSide) + " per side");
  require(s.L >= 0 && s.L <= kMaxLevel,
          what + ": max level " + std::to_string(s.L) + " is out of range 0.." + std::to_string(kMaxLevel));
}

Balance balance_option(const std::string& text) {
  const std::optional<Balance> b = parse_balance(text);
  if (!b) throw InputError("balance '" + text + "' is unknown: use edge or corner");
  return *b;
}

std::optional<std::string> corner_violation(const Graph& g) {
  const auto bad = find_corner_imbalance(g);
  if (!bad) return std::nullopt;
  return "corner balance: cell " + to_string(bad->first) + " (level " + std::to_string(g.level_of(bad->first)) +
         ") touches cell " + to_string(bad->second) + " (level " + std::to_string(g.level_of(bad->second)) + ")";
}

void run_check(const Graph& g, Balance balance, const std::string& when) {
  if (const std::optional<Violation> v = find_violation(g))
    throw CheckFailure("invariant violated " + when + ": " + to_string(*v));
  if (balance == Balance::Corner)
    if (const auto why = corner_violation(g)) throw CheckFailure("invariant violated " + when + ": " + *why);
}

std::string levels_text(const Graph& g, std::string& json) {
  std::map<int, std::size_t> per_level;
  for (const auto& [c, l] : g.level) ++per_level[l];
  return levels_text(per_level, json);
}

std::string levels_text(const std::map<int, std::size_t>& per_level, std::string& json) {
  std::string text;
  json = "{";
  for (const auto& [l, n] : per_level) {
    if (!text.empty()) text += ' ';
    text += std::to_string(l) + ':' + std::to_string(n);
    if (json.size() > 1) json += ", ";
    json += '"' + std::to_string(l) + "\": " + std::to_string(n);
  }
  json += "}";
  return text;
}

void Record::add(const std::string& name, const std::string& text, bool quoted) {
  items_.push_back({name, text, quoted, {}});
}

void Record::add(const std::string& name, double v) { add(name, std::isfinite(v) ? fmt(v, "%.9g") : "null", false); }

void Record::add_raw_json(const std::string& name, const std::string& json, const std::string& text) {
  items_.push_back({name, text, false, json});
}

std::string Record::text() const {
  std::string out;
  for (const auto& it : items_) out += it.name + " " + it.text + "\n";
  return out;
}

std::string Record::json() const {
  std::string out = "{";
  for (std::size_t i = 0; i < items_.size(); ++i) {
    const auto& it = items_[i];
    out += (i ? ", " : "") + json_string(it.name) + ": " +
           (!it.json.empty() ? it.json
            : it.quoted      ? json_string(it.text)
                             : it.text);
  }
  return out + "}";
}

}  // namespace bccmis::cli
