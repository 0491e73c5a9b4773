#pragma once
// Errors for bad user input. Messages name what and where (file, line, column or option) and
// what was expected; the command line prints them on one line and exits non-zero.

#include <stdexcept>
#include <string>

namespace ballsight {

/// Bad input from a user: a file, an image, a request or an option.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws InputError("<where>: <what>") when `ok` is false.
inline void require(bool ok, const std::string& where, const std::string& what) {
  if (!ok) throw InputError(where + ": " + what);
}

}  // namespace ballsight
