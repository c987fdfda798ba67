#pragma once
// What the case's readers had to say, printed for the user.

#include <string>
#include <vector>

namespace grainload::app {

/// The readers' lines for the user (io::CaseDocument::take_notices: warnings, notes), one a
/// line on stderr in their order. The library keeps them; the command line prints them.
void print_notices(const std::vector<std::string>& notices);

} // namespace grainload::app
