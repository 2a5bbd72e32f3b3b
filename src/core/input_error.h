// User-facing errors: bad scene files, bad options, unwritable outputs. Exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace rayrad {

/// An error in what the user gave us. The message already names the file and the place
/// in it ("scenes/cube.json: /lights/0/intensity_cd: expected a positive number, got -5").
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Builds "file: place: what", leaving out empty parts.
std::string placeMessage(const std::string& file, const std::string& place, const std::string& what);

}  // namespace rayrad
