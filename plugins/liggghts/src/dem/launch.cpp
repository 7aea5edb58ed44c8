// LIGGGHTS runs (see launch.h) through core's process runner: no shell (paths with spaces or
// quotes cannot break the command), and the engine dies with granlub.
#include "launch.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/run/process.h"
#include "granlub/run/progress.h"

namespace granlub::dem {

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::size_t count_lines(const fs::path& p) {
    std::ifstream in(p);
    std::size_t n = 0;
    std::string l;
    while (std::getline(in, l))
        if (!l.empty() && l[0] != '#') ++n;
    return n;
}

// The first "ERROR..." line of LIGGGHTS' output, or its last non-empty line.
std::string error_line(const fs::path& out) {
    std::ifstream in(out);
    std::string l, last;
    while (std::getline(in, l)) {
        if (l.rfind("ERROR", 0) == 0) return l;
        if (!l.empty()) last = l;
    }
    return last.empty() ? "(no output)" : last;
}

}  // namespace

fs::path find_driver() {
    std::vector<std::string> looked;
    if (const char* env = std::getenv("GRANLUB_LIGGGHTS_DRIVER")) {
        // absolute: the engine starts in the point's folder
        if (const auto p = find_executable(env)) return fs::absolute(*p);
        looked.push_back(fmt::format("$GRANLUB_LIGGGHTS_DRIVER = {}", env));
    }
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path next = self.parent_path() / "granlub-liggghts";
        if (find_executable(next.string())) return next;
        looked.push_back(next.string());
    }
#ifdef GRANLUB_LIGGGHTS_DRIVER_BUILD
    if (find_executable(GRANLUB_LIGGGHTS_DRIVER_BUILD)) return GRANLUB_LIGGGHTS_DRIVER_BUILD;
    looked.push_back(GRANLUB_LIGGGHTS_DRIVER_BUILD);
#endif
    if (auto p = find_executable("granlub-liggghts")) return *p;
    looked.push_back("PATH");
    std::string where;
    for (const auto& l : looked) where += "\n  " + l;
    throw SolverError("granlub dem: the LIGGGHTS driver granlub-liggghts was not found; looked in:" + where +
                      "\nBuild it (cmake --build <build> --target granlub-liggghts; needs Debian's liggghts and "
                      "libliggghts-dev) or set GRANLUB_LIGGGHTS_DRIVER to its path.");
}

EngineRun run_engine(const fs::path& dir, const std::string& deck, int np, std::int64_t total_steps,
                     const std::string& progress_file, std::int64_t steps_per_line, const std::string& label) {
    EngineRun r;
    r.ranks = std::max(1, np);
    const fs::path driver = find_driver();
    if (r.ranks > 1) {
        const auto mpirun = find_executable("mpirun");
        if (!mpirun)
            throw SolverError(fmt::format("granlub dem --np {}: mpirun was not found on PATH (Debian: openmpi-bin)",
                                          r.ranks));
        r.command = {mpirun->string(), "-np", std::to_string(r.ranks), "--oversubscribe"};
        if (::geteuid() == 0) r.command.push_back("--allow-run-as-root");
    }
    for (const auto& a : {driver.string(), std::string("-in"), deck, std::string("-log"), std::string("log.liggghts"),
                          std::string("-echo"), std::string("none")})
        r.command.push_back(a);

    // absolute: the child changes into `dir` before opening it (a relative results root broke this)
    const fs::path out = fs::absolute(dir / "liggghts.out");
    fs::remove(out);  // the runner appends; this run's output only
    fs::remove(dir / progress_file);
    ProcessResult pr;
    {
        Progress progress(label, static_cast<std::uint64_t>(std::max<std::int64_t>(1, total_steps)));
        auto poll = [&] {
            if (!progress.due()) return;  // the output file is read only when a line will be written
            const auto done = static_cast<std::int64_t>(count_lines(dir / progress_file)) * steps_per_line;
            progress.update(static_cast<std::uint64_t>(std::min(done, total_steps)), "LIGGGHTS");
        };
        pr = run_process(r.command, dir, out, 0, poll);  // no time limit: a DEM run may take hours
    }
    r.wall_clock_s = pr.seconds;
    if (pr.exit_code != 0)
        throw SolverError(fmt::format("LIGGGHTS failed ({}) in {}: {}\n  command: {}\n  output: {}", pr.describe(),
                                      dir.string(), error_line(out), fmt::join(r.command, " "), out.string()));
    static const std::regex loop(R"(Loop time of ([0-9.eE+-]+) on)");
    const std::string text = read_text(dir / "log.liggghts");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), loop); it != std::sregex_iterator(); ++it)
        r.loop_time_s += std::stod((*it)[1].str());  // load control runs the servo windows one by one
    return r;
}

}  // namespace granlub::dem
