#pragma once
// Order statistics for robust estimates.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace ballsight {

/// The median of `values`, not empty: element size / 2 in sorted order (the upper of the two
/// middle ones for an even count). Takes the values by value: pass them with std::move when
/// they are not needed after.
template <class T>
double median(std::vector<T> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return static_cast<double>(*middle);
}

}  // namespace ballsight
