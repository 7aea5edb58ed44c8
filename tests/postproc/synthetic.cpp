#include "synthetic.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "case_text.h"
#include "granlub/results/run_status.h"
#include "granlub/results/results.h"
#include "granlub/run/solver_info.h"

namespace granlub::test {

namespace {
int no_map(const Case&, const RunOptions&, int, int) { return 0; }
// The four solvers as their modules declare what the report reads of them (granlub/<module>/command.h).
constexpr SolverInfo kSolvers[] = {
    {.name = "continuum", .description = "", .kind = SolverKind::Continuum, .map = &no_map},
    {.name = "automaton", .description = "", .kind = SolverKind::Lattice},
    {.name = "dem", .description = "", .kind = SolverKind::Particles, .engine = true, .seeded = true, .ranks = true,
     .whole_ring = true, .bulk_rheology = true},
    {.name = "yade", .description = "", .kind = SolverKind::Particles, .engine = true, .seeded = true}};
}  // namespace

Schema synthetic_schema() {
    Schema s = Schema::common();
    for (const SolverInfo& solver : kSolvers) s.add(SectionSpec(solver.name, "")).declare_solver(solver.name, &solver);
    return s;
}

SyntheticCase make_case(const std::string& name, const std::string& extra_toml) {
    SyntheticCase s;
    s.dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / "postproc-tmp" / name;
    std::filesystem::remove_all(s.dir);
    std::filesystem::create_directories(s.dir);
    // tests/core/case_text.h's valid case, named, with a third speed and its own fill
    std::string text = with("name = \"t\"", "name = \"synthetic\"\ntitle = \"Synthetic results with known answers\"");
    text = with("speed = [1.0, 2.0]", "speed = [1.0, 2.0, 4.0]", text);
    text = with("solid_fraction = 0.5", "solid_fraction = 0.52", text);
    std::ofstream(s.dir / "case.toml") << text << extra_toml;
    s.c = load_case(s.dir, synthetic_schema());
    s.o.results_root = s.dir / "results";
    return s;
}

SyntheticCase edited_case(const std::string& name, const std::string& from, const std::string& to) {
    auto s = make_case(name);
    std::string text = slurp(s.dir / "case.toml");
    text.replace(text.find(from), from.size(), to);
    std::ofstream(s.dir / "case.toml") << text;
    s.c = load_case(s.dir, synthetic_schema());
    return s;
}

void write_solver(const SyntheticCase& s, const std::string& solver) {
    for (const OperatingPoint& p : s.c.points) {
        const double U = p.speed;
        std::vector<double> y, u, nu, T, se;
        Summary sum = make_summary(s.c, p, solver, solver == "continuum" ? std::nullopt : std::optional<std::uint64_t>(7));
        sum.kind = solver == "continuum" ? "continuum" : solver == "automaton" ? "lattice" : "particles";
        if (solver == "continuum") {
            for (int k = 0; k <= 40; ++k) y.push_back(k / 40.0);
            for (double v : y) u.push_back(0.9 - 0.8 * v), nu.push_back(0.65 * (0.8 + 0.1 * v)), T.push_back(0.01);
            sum.set("normal_stress_bottom", 1000 * U * U, "Pa").set("normal_stress_top", 900 * U * U, "Pa");
            sum.set("shear_stress_bottom", 400 * U * U, "Pa").set("shear_stress_top", 400 * U * U, "Pa");
            sum.set("slip_bottom", 0.1 * U, "m/s").set("slip_top", 0.1 * U, "m/s");
            sum.set("mean_solid_fraction", 0.55, "").set("max_solid_fraction", 0.65, "");
        } else if (solver == "dem" || solver == "yade") {  // yade: the dem's numbers 8 % lower
            for (int k = 0; k < 20; ++k) y.push_back((k + 0.5) / 20.0);
            for (double v : y)
                u.push_back(0.95 - 0.8 * v), nu.push_back(0.65 * (0.8 + 0.1 * v)), T.push_back(0.012), se.push_back(0.01);
            const double f = std::pow(U, 1.5) * (solver == "yade" ? 0.92 : 1.0);
            sum.set("normal_stress_bottom", 1100 * f, "Pa", 0.05 * 1100 * f)
                .set("normal_stress_top", 1000 * f, "Pa", 0.05 * 1000 * f);
            sum.set("shear_stress_bottom", 450 * f, "Pa", 0.05 * 450 * f).set("shear_stress_top", 450 * f, "Pa", 0.05 * 450 * f);
            sum.set("slip_bottom", 0.12 * U, "m/s", 0.01 * U).set("slip_top", 0.12 * U, "m/s", 0.01 * U);
            sum.set("mean_solid_fraction", 0.56, "", 0.005).set("max_solid_fraction", 0.65, "");
        } else {
            for (int k = 0; k < 10; ++k) y.push_back((k + 0.5) / 10.0);
            for (double v : y) u.push_back(0.9 - 0.8 * v), nu.push_back(0.8 + 0.1 * v), T.push_back(0.01);
            sum.set("normal_stress_bottom", 900 * U * U, "Pa").set("normal_stress_top", 810 * U * U, "Pa");
            sum.set("shear_stress_bottom", 360 * U * U, "Pa").set("shear_stress_top", 360 * U * U, "Pa");
            sum.set("slip_bottom", 0.1 * U, "m/s").set("slip_top", 0.1 * U, "m/s");
            sum.set("mean_solid_fraction", 0.85, "").set("max_solid_fraction", 1.0, "");
        }
        Profile prof;
        prof.add("y_over_H", y).add("u_over_U", u).add("solid_fraction", nu).add("temperature_over_U2", T);
        if (!se.empty()) {
            prof.add("u_over_U_stderr", se).add("solid_fraction_stderr", se).add("temperature_over_U2_stderr", se);
        }
        sum.run = {{"steps", 1000}, {"wall_clock_s", 0.5}};
        set_regime(sum.run, RegimeStatus::Steady);
        write_result(result_dir(s.o.results_root, solver, p.id), prof, sum);
    }
}

void patch_run(const SyntheticCase& s, const std::string& solver, const std::string& point, const nlohmann::json& run) {
    const auto file = result_dir(s.o.results_root, solver, point) / "summary.json";
    auto j = nlohmann::json::parse(slurp(file));
    for (const auto& [key, value] : run.items()) {
        if (value.is_null()) j["run"].erase(key);
        else j["run"][key] = value;
    }
    write_file_atomic(file, j.dump(2));
}

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + p.string());
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

namespace {
std::vector<std::string> split_csv(const std::string& line) {
    std::vector<std::string> cells;
    std::string cur;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted) {
            if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') cur += '"', ++i;
            else if (ch == '"') quoted = false;
            else cur += ch;
        } else if (ch == '"') {
            quoted = true;
        } else if (ch == ',') {
            cells.push_back(cur), cur.clear();
        } else {
            cur += ch;
        }
    }
    cells.push_back(cur);
    return cells;
}
}  // namespace

std::map<std::string, std::string> read_metrics_row(const std::filesystem::path& csv, const std::string& kind,
                                                    const std::string& point, const std::string& quantity,
                                                    const std::string& a, const std::string& b) {
    std::istringstream in(slurp(csv));
    std::string line;
    std::vector<std::string> header;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        auto cells = split_csv(line);
        if (header.empty()) {
            header = cells;
            continue;
        }
        if (cells.size() != header.size()) throw std::runtime_error("metrics.csv: ragged row: " + line);
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < cells.size(); ++i) row[header[i]] = cells[i];
        if (row["kind"] == kind && row["point"] == point && row["quantity"] == quantity && row["solver_a"] == a &&
            row["solver_b"] == b)
            return row;
    }
    return {};
}

SyntheticCase main_job_results(const std::string& name) {
    SyntheticCase s = make_case(name);
    for (const char* solver : {"continuum", "automaton", "dem", "yade"}) write_solver(s, solver);
    patch_run(s, "dem", s.c.points.back().id,
              {{"status", "transient"}, {"status_reason", "no steady state detected in 0.1 s of simulated time"}});
    patch_run(s, "dem", s.c.points.front().id,
              {{"status", "dt-unconverged"}, {"status_reason", "halving the time step moved tau by 9 %"}});
    return s;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
    return n;
}

}  // namespace granlub::test
