// Internal invariant checks (pbrt util/check.h style): CHECK always, DCHECK in debug only.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace rayrad {

/// Thrown when an internal invariant fails: a bug in rayrad, never a user error.
class InternalError : public std::logic_error {
  public:
    using std::logic_error::logic_error;
};

namespace detail {
[[noreturn]] inline void checkFailed(const char* file, int line, const std::string& what) {
    std::ostringstream s;
    s << "internal error at " << file << ":" << line << ": " << what;
    throw InternalError(s.str());
}
}  // namespace detail

}  // namespace rayrad

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) ::rayrad::detail::checkFailed(__FILE__, __LINE__, "CHECK(" #cond ")"); \
    } while (0)

#define CHECK_EQ(a, b)                                                                    \
    do {                                                                                  \
        const auto& check_a_ = (a);                                                       \
        const auto& check_b_ = (b);                                                       \
        if (!(check_a_ == check_b_)) {                                                    \
            std::ostringstream check_s_;                                                  \
            check_s_ << "CHECK_EQ(" #a ", " #b ") with " << check_a_ << " != " << check_b_; \
            ::rayrad::detail::checkFailed(__FILE__, __LINE__, check_s_.str());            \
        }                                                                                 \
    } while (0)

#ifdef NDEBUG
#define DCHECK(cond) \
    do {             \
    } while (0)
#else
#define DCHECK(cond) CHECK(cond)
#endif
