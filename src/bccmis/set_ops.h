// bccmis: the set operations of the paper's equations, named like the math.
// A ∪ B -> unite(A, B), A \ B -> minus(A, B), A ∩ B -> intersect(A, B).
#pragma once

#include <algorithm>
#include <iterator>
#include <set>

namespace bccmis {

template <class T>
std::set<T> unite(const std::set<T>& a, const std::set<T>& b) {
  std::set<T> r;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::inserter(r, r.end()));
  return r;
}

template <class T>
std::set<T> minus(const std::set<T>& a, const std::set<T>& b) {
  std::set<T> r;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::inserter(r, r.end()));
  return r;
}

template <class T>
std::set<T> intersect(const std::set<T>& a, const std::set<T>& b) {
  std::set<T> r;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::inserter(r, r.end()));
  return r;
}

}  // namespace bccmis
