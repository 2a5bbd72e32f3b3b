#include <app/sweep.h>

#include <app/sensor_table.h>

#include <core/input_error.h>
#include <core/output_file.h>
#include <scene/scene_parser.h>

#include <fmt/format.h>

#include <filesystem>
#include <iostream>

namespace rayrad::app {

namespace {

constexpr size_t kMaxJobs = 100'000;

/// Splits on commas outside brackets and quotes.
std::vector<std::string> splitValues(const std::string& text) {
    std::vector<std::string> out(1);
    int depth = 0;
    bool quoted = false;
    for (char c : text) {
        if (c == '"') quoted = !quoted;
        if (!quoted && (c == '[' || c == '{')) ++depth;
        if (!quoted && (c == ']' || c == '}')) --depth;
        if (c == ',' && depth == 0 && !quoted) out.emplace_back();
        else out.back() += c;
    }
    return out;
}

/// The program's own absolute path, so the jobs run this rayrad from any directory.
std::string selfPath() {
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("rayrad") : p.string();
}

}  // namespace

std::pair<std::string, std::vector<std::string>> parseVary(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw InputError(placeMessage("", "--vary", "expected KEY=V1,V2,..., got \"" + text + "\""));
    auto values = splitValues(text.substr(eq + 1));
    for (const auto& v : values)
        if (v.empty()) throw InputError(placeMessage("", "--vary", "an empty value in \"" + text + "\""));
    // The jobs file is one job a line: a line break (or another control character) in a
    // key or value would split a job in two.
    for (unsigned char c : text)
        if (c < 0x20 || c == 0x7f)
            throw InputError(placeMessage("", "--vary", fmt::format("a control character (code {}) in the values of "
                                                                    "\"{}\": keys and values are one line each",
                                                                    static_cast<int>(c), text.substr(0, eq))));
    return {text.substr(0, eq), values};
}

std::string shellQuote(const std::string& word) {
    if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%") ==
                             std::string::npos)
        return word;
    std::string out = "'";
    for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

int writeSweep(const SweepOptions& o) {
    std::vector<std::pair<std::string, std::vector<std::string>>> axes;
    size_t jobs = 1;
    for (const auto& v : o.vary) {
        axes.push_back(parseVary(v));
        jobs *= axes.back().second.size();
        if (jobs > kMaxJobs)
            throw InputError(placeMessage("", "--vary", fmt::format("the grid has more than {} jobs", kMaxJobs)));
    }
    if (o.command.find("--set") != std::string::npos)
        throw InputError(placeMessage("", "--run", "give the values to vary with --vary, not --set in the command"));
    const std::string csvFile = std::filesystem::path(o.jobsFile).replace_extension(".csv").string();
    OutputFiles files;
    files.addInput(o.scene);
    files.add(o.jobsFile);
    files.add(csvFile);

    const int digits = static_cast<int>(std::to_string(jobs - 1).size());
    std::string lines, csv = "job";
    for (const auto& [key, unused] : axes) csv += "," + csvField(key);
    csv += "\n";
    const std::string rayrad = o.rayrad.empty() ? selfPath() : o.rayrad;
    for (size_t job = 0; job < jobs; ++job) {
        std::vector<scene::Override> overrides;
        std::string sets, row = std::to_string(job);
        size_t rest = job;
        for (size_t a = axes.size(); a-- > 0;) {  // the last axis changes fastest
            const auto& [key, values] = axes[a];
            overrides.insert(overrides.begin(), {key, values[rest % values.size()]});
            rest /= values.size();
        }
        for (const auto& ov : overrides) {
            sets += " --set " + shellQuote(ov.path + "=" + ov.value);
            row += "," + csvField(ov.value);
        }
        try {
            scene::loadScene(o.scene, overrides);  // a value the scene refuses is found now, not on the farm
        } catch (const InputError& e) {
            throw InputError(fmt::format("job {} ({}): {}", job, row.substr(row.find(',') + 1), e.what()));
        }
        std::string command = o.command;
        const std::string number = fmt::format("{:0{}d}", job, digits);
        for (size_t at = command.find("{job}"); at != std::string::npos; at = command.find("{job}", at + number.size()))
            command.replace(at, 5, number);
        lines += shellQuote(rayrad) + " " + command + " " + shellQuote(o.scene) + sets + "\n";
        csv += row + "\n";
    }
    files.set(o.jobsFile, lines);
    files.set(csvFile, csv);
    files.commit();
    std::cerr << fmt::format("sweep: {} jobs in {} (their values in {}); run them with\n"
                             "  parallel --jobs N < {}\n"
                             "or as a Slurm job array: sbatch --array=0-{} scripts/slurm/sweep.sbatch {}\n",
                             jobs, o.jobsFile, csvFile, shellQuote(o.jobsFile), jobs - 1, shellQuote(o.jobsFile));
    return 0;
}

}  // namespace rayrad::app
