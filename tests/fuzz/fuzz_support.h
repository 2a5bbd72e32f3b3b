// What every fuzz target checks: bad input may only come back as an InputError (a clear
// message, exit code 2 in the tool); any other exception is a finding, as are crashes,
// hangs and sanitizer reports.
#pragma once

#include <core/input_error.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace rayrad::fuzz {

template <class Read>
int onlyInputErrors(Read&& read) {
    try {
        read();
    } catch (const InputError&) {
        // The expected way to reject an input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "finding: %s escaped as a non-input error\n", e.what());
        std::abort();
    }
    return 0;
}

}  // namespace rayrad::fuzz
