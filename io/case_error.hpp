#pragma once
// Bad input: the error whose message names file, line, column and key (exit code 2).

#include <stdexcept>
#include <string>

namespace grainload::io {

/// Bad input: a case file, a mesh file or a command-line override. The message already names
/// the file, line, column and key; the CLI prints it and exits with code 2.
class CaseError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

} // namespace grainload::io
