#include "app/notices.hpp"

#include <iostream>

namespace grainload::app {

void print_notices(const std::vector<std::string>& notices) {
    for (const std::string& line : notices) {
        std::cerr << line << '\n';
    }
}

} // namespace grainload::app
