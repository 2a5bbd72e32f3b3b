// The source tree's shape: every #include of src/ runs one way along the data flow.
// core ← scene ← radiosity ← raytrace ← app, tonemap ← core; inside radiosity the
// sub-stage folders in the order below; raytrace and app see radiosity only through its
// front door (radiosity/radiosity.h); and no file includes, through any chain, itself.
#include "test_support.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// The modules in the order of the data flow: a module may include itself and the
/// modules before it, except where allowedToInclude says otherwise.
const std::vector<std::string> kOrder = {
    "core",
    "scene",
    "tonemap",
    "image_module",  // implements tonemap/image_library.h; loaded, not linked
    "radiosity/mesh",
    "radiosity/form_factors",
    "radiosity/mirrors",
    "radiosity/solution",
    "radiosity/direct",
    "radiosity/clusters",
    "radiosity/shooting",
    "radiosity/gather",
    "radiosity/display",
    "radiosity",  // the front door
    "raytrace",
    "app",
};

/// "radiosity/gather" for src/radiosity/gather/gather.h, "radiosity" for
/// src/radiosity/radiosity.h, "app" for src/app/main.cpp.
std::string moduleOf(const std::string& relative) {
    const auto first = relative.find('/');
    const std::string top = relative.substr(0, first);
    if (top != "radiosity") return top;
    const auto second = relative.find('/', first + 1);
    return second == std::string::npos ? top : relative.substr(0, second);
}

int rank(const std::string& module) {
    const auto it = std::find(kOrder.begin(), kOrder.end(), module);
    return it == kOrder.end() ? -1 : static_cast<int>(it - kOrder.begin());
}

/// Why `from` may not include `header` (empty: it may).
std::string forbidden(const std::string& from, const std::string& header) {
    const std::string a = moduleOf(from), b = moduleOf(header);
    if (rank(a) < 0) return "file outside the known modules";
    if (rank(b) < 0) return "header outside the known modules";
    if (a == b) return "";
    if (rank(b) > rank(a)) return a + " may not include " + b + " (it comes later in the data flow)";
    if (a == "tonemap" && b != "core") return "tonemap depends on core only";
    if (a == "image_module" && b != "core" && b != "tonemap")
        return "the image module depends on core and tonemap only";
    if (b == "image_module") return "the image module is loaded (tonemap/image_library.h), not included";
    const bool outsideRadiosity = a == "raytrace" || a == "app";
    if (outsideRadiosity && b.rfind("radiosity/", 0) == 0)
        return a + " sees radiosity through its front door (radiosity/radiosity.h), not " + b;
    if (a.rfind("radiosity", 0) == 0 && b == "tonemap") return "radiosity does not depend on tonemap";
    return "";
}

struct Source {
    std::string relative;               ///< e.g. "radiosity/gather/gather.cpp"
    std::vector<std::string> includes;  ///< the project headers it includes, relative to src/
};

std::vector<Source> readSources(const fs::path& src) {
    const std::regex include(R"(^\s*#\s*include\s*<([a-z_]+/[^>]+\.h)>)");
    std::vector<Source> out;
    for (const auto& entry : fs::recursive_directory_iterator(src)) {
        const auto ext = entry.path().extension();
        if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
        Source s;
        s.relative = fs::relative(entry.path(), src).generic_string();
        std::ifstream in(entry.path());
        std::string line;
        std::smatch m;
        while (std::getline(in, line))
            if (std::regex_search(line, m, include) && fs::exists(src / m[1].str())) s.includes.push_back(m[1]);
        out.push_back(std::move(s));
    }
    std::sort(out.begin(), out.end(), [](const Source& x, const Source& y) { return x.relative < y.relative; });
    return out;
}

}  // namespace

TEST_CASE("includes run one way: stages, radiosity's sub-stages, its front door", "[layering]") {
    const fs::path src = rayrad::test::sourcePath("src");
    const auto sources = readSources(src);
    REQUIRE(sources.size() > 100);
    std::vector<std::string> problems;
    for (const auto& s : sources)
        for (const auto& h : s.includes)
            if (const std::string why = forbidden(s.relative, h); !why.empty())
                problems.push_back(s.relative + " includes " + h + ": " + why);
    INFO([&] {
        std::string all;
        for (const auto& p : problems) all += p + "\n";
        return all;
    }());
    CHECK(problems.empty());
}

TEST_CASE("no header includes itself through a chain of includes", "[layering]") {
    const fs::path src = rayrad::test::sourcePath("src");
    std::map<std::string, std::vector<std::string>> graph;
    for (const auto& s : readSources(src)) graph[s.relative] = s.includes;
    // Depth-first search; a header met again while on the stack closes a cycle.
    std::map<std::string, int> state;  // 0 new, 1 on the stack, 2 done
    std::vector<std::string> stack, cycles;
    std::function<void(const std::string&)> visit = [&](const std::string& f) {
        state[f] = 1;
        stack.push_back(f);
        for (const auto& h : graph[f]) {
            if (state[h] == 1) {
                std::string cycle;
                for (auto it = std::find(stack.begin(), stack.end(), h); it != stack.end(); ++it) cycle += *it + " → ";
                cycles.push_back(cycle + h);
            } else if (state[h] == 0) {
                visit(h);
            }
        }
        stack.pop_back();
        state[f] = 2;
    };
    for (const auto& [file, includes] : graph)
        if (state[file] == 0) visit(file);
    INFO([&] {
        std::string all;
        for (const auto& c : cycles) all += c + "\n";
        return all;
    }());
    CHECK(cycles.empty());
}
