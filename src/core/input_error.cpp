#include <core/input_error.h>

namespace rayrad {

std::string placeMessage(const std::string& file, const std::string& place, const std::string& what) {
    std::string s;
    if (!file.empty()) s += file + ": ";
    if (!place.empty()) s += place + ": ";
    return s + what;
}

}  // namespace rayrad
