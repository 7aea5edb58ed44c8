// Runs granlub-liggghts on a deck, as the LIGGGHTS tests do, and reads its RESULT lines.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace granlub::test {

struct DriverRun {
    std::string output;  // stdout + stderr
    int exit_code;       // the driver's (mpirun's) exit status; -1 if it did not exit normally
};

// Runs a shell command line, collecting its output and exit status.
inline DriverRun run_command(const std::string& cmd) {
    DriverRun run{"", -1};
    FILE* p = ::popen(cmd.c_str(), "r");
    if (!p) return run;
    std::array<char, 4096> buf;
    while (std::fgets(buf.data(), buf.size(), p)) run.output += buf.data();
    const int status = ::pclose(p);
    if (status != -1 && WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
    return run;
}

// Runs the driver on `np` ranks in <build>/tests/<folder>, with extra command-line `vars`.
inline DriverRun run_driver(const std::string& deck, const std::string& vars, int np = 1,
                            const std::string& folder = "liggghts_collide") {
    const std::filesystem::path dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / folder;
    std::filesystem::create_directories(dir);
    std::string cmd = "cd '" + dir.string() + "' && ";
    if (np > 1) {
        cmd += "mpirun -np " + std::to_string(np) + " --oversubscribe ";
        if (::geteuid() == 0) cmd += "--allow-run-as-root ";
    }
    cmd += std::string(GRANLUB_LIGGGHTS_DRIVER_PATH) + " -in '" + deck + "' -log none -echo none " + vars + " 2>&1";
    return run_command(cmd);
}

// name=value pairs of the RESULT lines (the measured part, before any "expect")
inline std::map<std::string, double> results(const std::string& out) {
    std::map<std::string, double> r;
    static const std::regex kv(R"(([a-z]+[0-9]+)=([-+0-9.eE]+))");
    std::istringstream ss(out);
    std::string line;
    while (std::getline(ss, line)) {
        if (line.rfind("RESULT", 0) != 0) continue;
        const std::string measured = line.substr(0, line.find("expect"));
        for (auto it = std::sregex_iterator(measured.begin(), measured.end(), kv); it != std::sregex_iterator(); ++it)
            r[(*it)[1].str()] = std::stod((*it)[2].str());
    }
    return r;
}

inline std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The command lines of a LIGGGHTS doc page's first [Examples:] block (up to the line ending in ":pre").
inline std::vector<std::string> example_lines(const std::filesystem::path& page) {
    std::istringstream in(read_text(page));
    std::vector<std::string> lines;
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line == "[Examples:]") {
            inside = true;
            continue;
        }
        if (!inside || line.empty()) continue;
        const bool last = line.size() >= 4 && line.compare(line.size() - 4, 4, ":pre") == 0;
        if (last) line = std::regex_replace(line, std::regex(R"(\s*:pre$)"), "");
        lines.push_back(line);
        if (last) break;
    }
    return lines;
}

}  // namespace granlub::test
