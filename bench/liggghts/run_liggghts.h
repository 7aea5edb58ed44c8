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
#include <vector>

namespace granlub::bench {

struct Measured {
    double loop_s = 0;      // loop time of the timed (last) run, wall clock
    std::vector<double> loops;  // the loop times of every run of the deck, in order (its phases)
    double cpu_s = 0;       // user + sys CPU of the whole process tree (all runs, all ranks)
    double atoms = 0;
    double steps = 0;       // timed steps
    double all_steps = 0;   // warm-up + timed
    double dt = 0;
    int ranks = 1;
    // LIGGGHTS' own statistics of the timed run (its last "Loop time" block)
    double pair_s = 0;        // "Pair time"
    double neigh_s = 0;       // "Neigh time"
    double neighbours = 0;    // "Ave neighs/atom": listed pairs per grain (a half list)
    double builds = 0;        // "Neighbor list builds"
    double ns_per_grain_step() const { return 1e9 * loop_s / (atoms * steps); }
    // Pair and Neigh per grain-step; the pair loop per listed pair and step; the neighbour build
    // per grain and build (on several ranks LIGGGHTS' times are per rank, its counts global)
    double pair_ns_per_grain_step() const { return 1e9 * pair_s / (atoms * steps); }
    double neigh_ns_per_grain_step() const { return 1e9 * neigh_s / (atoms * steps); }
    double pair_ns_per_listed_pair() const { return pair_ns_per_grain_step() / neighbours; }
    double neigh_ns_per_grain_build() const { return builds > 0 ? 1e9 * neigh_s / (atoms * builds) : 0; }
    double builds_per_1000_steps() const { return 1000.0 * builds / steps; }
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
    m.ranks = np;
    m.cpu_s = children_cpu() - cpu0;
    static const std::regex loop(R"(Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms)");
    size_t last = std::string::npos;
    for (auto it = std::sregex_iterator(out.begin(), out.end(), loop); it != std::sregex_iterator(); ++it) {
        m.loop_s = std::stod((*it)[1].str());
        m.loops.push_back(m.loop_s);
        m.atoms = std::stod((*it)[3].str());
        last = static_cast<size_t>(it->position(0));
    }
    if (last == std::string::npos) return m;
    // the statistics after the last loop time; a field LIGGGHTS did not print stays 0
    const std::string tail = out.substr(last);
    auto field = [&tail](const char* re) {
        std::smatch hit;
        return std::regex_search(tail, hit, std::regex(re)) ? std::stod(hit[1].str()) : 0.0;
    };
    m.pair_s = field(R"(Pair\s+time \(%\) = ([0-9.eE+-]+))");
    m.neigh_s = field(R"(Neigh\s+time \(%\) = ([0-9.eE+-]+))");
    m.neighbours = field(R"(Ave neighs/atom = ([0-9.eE+-]+))");
    m.builds = field(R"(Neighbor list builds = (\d+))");
    return m;
}

}  // namespace granlub::bench
