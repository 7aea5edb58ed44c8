// Running granlub-liggghts from a benchmark: one command line, LIGGGHTS' loop time of the last
// run (wall clock) and the CPU time of the whole process tree (the machine may be shared: CPU
// time is the steadier number).
#pragma once
#include <sys/resource.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <regex>
#include <string>

namespace granlub::bench {

struct Measured {
    double loop_s = 0;      // loop time of the timed (last) run, wall clock
    double cpu_s = 0;       // user + sys CPU of the whole process tree (all runs, all ranks)
    double atoms = 0;
    double steps = 0;       // timed steps
    double all_steps = 0;   // warm-up + timed
    double dt = 0;
    double ns_per_grain_step() const { return 1e9 * loop_s / (atoms * steps); }
    double cpu_ns_per_grain_step() const { return 1e9 * cpu_s / (atoms * all_steps); }
};

inline double children_cpu() {
    rusage u{};
    ::getrusage(RUSAGE_CHILDREN, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// `cd dir && [mpirun -np np] granlub-liggghts -in deck -log none -echo none vars`; loop_s stays 0
// when the run printed no loop time (it failed).
inline Measured run_liggghts(const std::string& dir, const std::string& deck, const std::string& vars, int np) {
    std::string cmd = "cd '" + dir + "' && ";
    if (np > 1) {
        cmd += "mpirun -np " + std::to_string(np) + " --oversubscribe ";
        if (::geteuid() == 0) cmd += "--allow-run-as-root ";
    }
    cmd += std::string(GRANLUB_LIGGGHTS_DRIVER_PATH) + " -in '" + deck + "' -log none -echo none " + vars + " 2>&1";
    const double cpu0 = children_cpu();
    std::string out;
    FILE* p = ::popen(cmd.c_str(), "r");
    std::array<char, 4096> buf;
    while (p && std::fgets(buf.data(), buf.size(), p)) out += buf.data();
    if (p) ::pclose(p);
    Measured m;
    m.cpu_s = children_cpu() - cpu0;
    static const std::regex loop(R"(Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms)");
    for (auto it = std::sregex_iterator(out.begin(), out.end(), loop); it != std::sregex_iterator(); ++it) {
        m.loop_s = std::stod((*it)[1].str());
        m.atoms = std::stod((*it)[3].str());
    }
    return m;
}

}  // namespace granlub::bench
