// The entry point of a bench tool: -h/--help prints its usage, and an error in the input
// (a scene, a setting) or in the run ends it with a message and an exit code, not an
// uncaught exception (exit codes as rayrad's: 2 bad input, 1 any other error).
#pragma once

#include <core/input_error.h>

#include <cstdio>
#include <cstring>
#include <exception>

namespace rayrad::bench {

/// Runs body() unless the arguments ask for help; `usage` is printed for -h or --help.
template <class Body>
int runBench(const char* name, const char* usage, int argc, char** argv, Body body) {
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
            std::fputs(usage, stdout);
            return 0;
        }
    try {
        return body();
    } catch (const InputError& e) {
        std::fprintf(stderr, "%s: %s\n", name, e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: error: %s\n", name, e.what());
        return 1;
    }
}

}  // namespace rayrad::bench
