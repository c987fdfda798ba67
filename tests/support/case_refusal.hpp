#pragma once
// The message with which a reader or a scene check refuses a case, for tests that assert it.

#include "io/case_error.hpp"

#include <string>

namespace grainload::testing {

/// The CaseError's message of `action`, "" when it throws none.
template <class Action> std::string refusal(Action&& action) {
    try {
        action();
    } catch (const io::CaseError& e) {
        return e.what();
    }
    return "";
}

} // namespace grainload::testing
