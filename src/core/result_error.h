// A result that must not be handed over: non-finite values, an image with no light in
// it. Exit code 4; nothing is written. The message names the cause when it is known.
#pragma once

#include <stdexcept>

namespace rayrad {

class ResultError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace rayrad
