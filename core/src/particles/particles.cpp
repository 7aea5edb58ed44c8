// Particle sets, overlap-free insertion and the initial-configuration file (see particles.h).
#include "granlub/particles/particles.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <random>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "granlub/particles/annulus.h"
#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/text.h"
#include "granlub/results/results.h"
#include "granlub/results/run_id.h"
#include "granlub/results/table.h"
#include "granlub/case/wall_bumps.h"
#include "lattice_insertion.h"

namespace granlub {

namespace {
constexpr const char* kHeader = "x,y,z,vx,vy,vz,radius";
constexpr const char* kSpinHeader = "x,y,z,vx,vy,vz,radius,wx,wy,wz";
}  // namespace

void ParticleSet::reserve(std::size_t n) {
    for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &radius}) v->reserve(n);
}

void ParticleSet::clear() {
    for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &radius, &wx, &wy, &wz}) v->clear();
}

void ParticleSet::push_back(double x_, double y_, double z_, double vx_, double vy_, double vz_, double r) {
    x.push_back(x_);
    y.push_back(y_);
    z.push_back(z_);
    vx.push_back(vx_);
    vy.push_back(vy_);
    vz.push_back(vz_);
    radius.push_back(r);
}

std::size_t grains_for_fill(const ParticleBox& box, const GrainSizes& sizes, double nu) {
    const double n = nu * box.volume() / sizes.mean_volume();
    if (!(n <= kMaxGrains))
        throw CaseError(fmt::format("{:.3g} grains of d = {:g} m fill the {:g} x {:g} x {:g} m box at solid fraction "
                                    "{:g}; at most {:g} are allowed (a smaller [cell] length, gap or width)",
                                    n, sizes.mean, box.length, box.gap, box.width, nu, kMaxGrains));
    return static_cast<std::size_t>(std::llround(n));
}

std::size_t grains_for_fill(const ParticleBox& box, double diameter, double nu) {
    return grains_for_fill(box, GrainSizes{diameter, 0.0}, nu);
}

namespace {

// FCC sites: hexagonal x-z layers (rows along x, spacing a; rows sqrt(3)/2 a apart) stacked
// ABC along y, sqrt(2/3) a apart. Each axis is then stretched to fill the box exactly, which
// never brings two sites closer than a. `jitter` of room is kept at every wall.
struct Lattice {
    std::size_t nx = 0, ny = 0, nz = 0;
    double ax = 0, ay = 0, az = 0;
    double y0 = 0, z0 = 0, jitter = 0;
    std::size_t count() const { return nx * ny * nz; }
};

Lattice make_lattice(const ParticleBox& box, double d, double a) {
    Lattice l;
    l.jitter = 0.5 * (a - d);
    const double margin = l.jitter + 1e-9 * d;  // keeps a strict gap to every wall
    l.nx = static_cast<std::size_t>(std::floor(box.length / a));
    l.ax = l.nx > 0 ? box.length / static_cast<double>(l.nx) : 0.0;

    const double hy = box.gap - d - 2.0 * margin;  // range of centre y
    const double ay = a * std::sqrt(2.0 / 3.0);
    l.ny = hy < 0 ? 0 : static_cast<std::size_t>(std::floor(hy / ay)) + 1;
    l.ay = l.ny > 1 ? hy / static_cast<double>(l.ny - 1) : 0.0;
    l.y0 = 0.5 * d + margin;

    const double az = a * std::sqrt(3.0) / 2.0;
    if (box.periodic_z) {
        std::size_t nz = static_cast<std::size_t>(std::floor(box.width / az));
        nz -= nz % 2;  // rows alternate their x offset: an even count keeps the period
        l.nz = nz;
        l.az = nz > 0 ? box.width / static_cast<double>(nz) : 0.0;
        l.z0 = -0.5 * box.width;
    } else {
        // rows at z0 + (j + s) az with the stacking shift s in {0, 1/3, 2/3}
        const double hz = box.width - d - 2.0 * margin;
        const double k = hz / az - 2.0 / 3.0;
        l.nz = k < 0 ? 0 : static_cast<std::size_t>(std::floor(k)) + 1;
        l.az = l.nz > 0 ? hz / (static_cast<double>(l.nz) - 1.0 + 2.0 / 3.0) : 0.0;
        l.z0 = -0.5 * box.width + 0.5 * d + margin;
    }
    return l;
}

void site(const Lattice& l, std::size_t s, double& x, double& y, double& z) {
    const std::size_t i = s % l.nx;
    const std::size_t j = (s / l.nx) % l.nz;
    const std::size_t k = s / (l.nx * l.nz);
    const double shift = static_cast<double>(k % 3);  // A, B, C layers
    const double xoff = 0.5 * static_cast<double>(j % 2) + (k % 3 == 1 ? 0.5 : 0.0);
    x = (static_cast<double>(i) + xoff) * l.ax;
    z = l.z0 + (static_cast<double>(j) + shift / 3.0) * l.az;
    y = l.y0 + static_cast<double>(k) * l.ay;
}

double wrap(double v, double period) {
    v = std::fmod(v, period);
    return v < 0 ? v + period : v;
}

}  // namespace

// Throws CaseError when n grains cannot sit on the densest insertion lattice (spaced for the
// largest grain).
static void check_fits(const ParticleBox& box, const GrainSizes& g, std::size_t n) {
    const Lattice densest = make_lattice(box, g.max(), g.max());
    if (densest.count() < n) {
        const double vg = g.mean_volume();
        throw CaseError(fmt::format(
            "particle insertion: {} grains (solid fraction {:.4f}) do not fit without overlaps in the "
            "{:g} x {:g} x {:g} m box{}; at most {} grains (solid fraction {:.4f}) can be inserted",
            n, static_cast<double>(n) * vg / box.volume(), box.length, box.gap, box.width,
            g.equal() ? "" : fmt::format(" on a lattice spaced for the largest grain ({:g} m)", g.max()),
            densest.count(), static_cast<double>(densest.count()) * vg / box.volume()));
    }
}

ParticleSet insert_grains(const ParticleBox& box, double d_mean, std::size_t n, const InsertionOptions& opt) {
    const GrainSizes g{d_mean, opt.size_spread};
    const double d = g.max();  // sites and wall margins for the largest grain
    if (!(d > 0) || !(box.length > 0) || !(box.gap > 0) || !(box.width > 0))
        throw CaseError(fmt::format("particle insertion: grain diameter {:g} m and box {:g} x {:g} x {:g} m must "
                                    "be positive",
                                    d, box.length, box.gap, box.width));
    check_fits(box, g, n);
    const double a = largest_spacing(d, n, [&](double s) { return make_lattice(box, d, s).count(); });
    const Lattice l = make_lattice(box, d, a);
    const std::vector<double> diameters = draw_diameters(g, n, opt.seed);
    Rng rng(opt.seed);
    const std::vector<std::size_t> sites = random_sites(rng, l.count(), n);

    ParticleSet p;
    p.reserve(n);
    const double sigma = opt.velocity_noise * std::abs(opt.wall_speed);
    for (std::size_t k = 0; k < n; ++k) {
        double x, y, z;
        site(l, sites[k], x, y, z);
        double dx, dy, dz;
        // each grain moves at most (a - d_i) / 2 from its site: no overlap with a neighbour or a wall
        ball_jitter(rng, g.equal() ? l.jitter : 0.5 * (a - diameters[k]), dx, dy, dz);
        x = wrap(x + dx, box.length);
        y += dy;
        z += dz;
        if (box.periodic_z) z = wrap(z + 0.5 * box.width, box.width) - 0.5 * box.width;
        const double u = opt.wall_speed * (1.0 - y / box.gap);
        y += opt.floor;
        const double vx = u + sigma * rng.normal();
        const double vy = sigma * rng.normal();
        const double vz = sigma * rng.normal();
        p.push_back(x, y, z, vx, vy, vz, 0.5 * diameters[k]);
    }
    return p;
}

double min_gap(const ParticleSet& p, const ParticleBox& box) {
    double best = std::numeric_limits<double>::infinity();
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
        best = std::min({best, p.y[i] - p.radius[i], box.gap - p.y[i] - p.radius[i]});
        if (!box.periodic_z)
            best = std::min({best, p.z[i] + 0.5 * box.width - p.radius[i], 0.5 * box.width - p.z[i] - p.radius[i]});
        for (std::size_t j = i + 1; j < n; ++j) {  // O(n^2): for checks and tests only
            double dx = p.x[j] - p.x[i];
            dx -= box.length * std::round(dx / box.length);
            const double dy = p.y[j] - p.y[i];
            double dz = p.z[j] - p.z[i];
            if (box.periodic_z) dz -= box.width * std::round(dz / box.width);
            best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz) - p.radius[i] - p.radius[j]);
        }
    }
    return best;
}

double solid_fraction(const ParticleSet& p, const ParticleBox& box) {
    double v = 0;
    for (double r : p.radius) v += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    return v / box.volume();
}

double solids_volume(const ParticleSet& p) {
    if (p.size() == 0) return 0.0;
    const double r0 = p.radius.front();
    if (std::all_of(p.radius.begin(), p.radius.end(), [&](double r) { return r == r0; }))
        return static_cast<double>(p.size()) * (std::numbers::pi / 6.0 * std::pow(2.0 * r0, 3));
    double v = 0;
    for (double r : p.radius) v += std::numbers::pi / 6.0 * std::pow(2.0 * r, 3);
    return v;
}

std::filesystem::path initial_particles_path(const std::filesystem::path& root, const std::string& point) {
    return root / "initial" / point / "particles.csv";
}

void write_particles_csv(const std::filesystem::path& path, const ParticleSet& p,
                         const std::vector<std::string>& comments) {
    std::string out;
    out.reserve(p.size() * 140 + 256);
    for (const auto& c : comments) out += "# " + one_line(c) + "\n";  // a path may hold a line break
    const bool spin = p.has_spin();
    if (spin && (p.wx.size() != p.size() || p.wy.size() != p.size() || p.wz.size() != p.size()))
        throw Error(fmt::format("internal: {}: {} grains but {} spins", path.string(), p.size(), p.wx.size()));
    out += std::string(spin ? kSpinHeader : kHeader) + "\n";
    for (std::size_t i = 0; i < p.size(); ++i) {
        out += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", p.x[i], p.y[i], p.z[i],
                           p.vx[i], p.vy[i], p.vz[i], p.radius[i]);
        out += spin ? fmt::format(",{:.17g},{:.17g},{:.17g}\n", p.wx[i], p.wy[i], p.wz[i]) : std::string("\n");
    }
    std::filesystem::create_directories(path.parent_path());
    write_file_atomic(path, out);
}

std::vector<std::string> read_particles_comments(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw Error(fmt::format("{}: cannot open the particles file", path.string()));
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l) && !l.empty() && l[0] == '#';) {
        if (l.back() == '\r') l.pop_back();
        out.push_back(l.size() >= 2 && l[1] == ' ' ? l.substr(2) : l.substr(1));
    }
    return out;
}

ParticleSet read_particles_csv(const std::filesystem::path& path) {
    TableFormat f;
    f.finite = true;
    Table t = read_table(path, f);
    const std::string header = fmt::format("{}", fmt::join(t.names, ","));
    const bool spin = header == kSpinHeader;
    if (!spin && header != kHeader)
        throw Error(fmt::format("{}: header '{}', expected '{}' or '{}'", path.string(), header, kHeader, kSpinHeader));
    for (std::size_t r = 0; r < t.rows(); ++r)
        if (!(t.columns[6][r] > 0))
            throw Error(fmt::format("{}:{}: radius {:g} must be positive", path.string(), t.line[r], t.columns[6][r]));
    ParticleSet p;
    p.x = std::move(t.columns[0]);
    p.y = std::move(t.columns[1]);
    p.z = std::move(t.columns[2]);
    p.vx = std::move(t.columns[3]);
    p.vy = std::move(t.columns[4]);
    p.vz = std::move(t.columns[5]);
    p.radius = std::move(t.columns[6]);
    if (spin) {
        p.wx = std::move(t.columns[7]);
        p.wy = std::move(t.columns[8]);
        p.wz = std::move(t.columns[9]);
    }
    return p;
}

std::filesystem::path final_state_path(const std::filesystem::path& root, const std::string& solver,
                                       const std::string& point) {
    return root / solver / point / kFinalStateFile;
}

void write_particle_state(const std::filesystem::path& path, const ParticleState& s, std::vector<std::string> comments) {
    comments.push_back(fmt::format("gap: {:.17g}", s.gap));
    comments.push_back(fmt::format("time: {:.17g}", s.time));
    comments.push_back(run_id_comment());  // a run's output (results.h), unlike the shared initial grains
    write_particles_csv(path, s.particles, comments);
}

ParticleState read_particle_state(const std::filesystem::path& path) {
    ParticleState s;
    s.particles = read_particles_csv(path);
    bool have_gap = false;
    for (const auto& c : read_particles_comments(path)) {
        auto value = [&](const char* key) -> std::optional<double> {
            if (c.rfind(key, 0) != 0) return std::nullopt;
            const std::string v = c.substr(std::string(key).size());
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            if (end == v.c_str() || *end != '\0' || !std::isfinite(x))
                throw Error(fmt::format("{}: comment '{}': not a number after '{}'", path.string(), c, key));
            return x;
        };
        if (auto g = value("gap: ")) s.gap = *g, have_gap = true;
        if (auto t = value("time: ")) s.time = *t;
    }
    if (!have_gap || !(s.gap > 0))
        throw Error(fmt::format("{}: no positive 'gap: <m>' comment (the top wall's position of the state)",
                                path.string()));
    return s;
}

namespace {
// The box the grain count comes from: the slice's, or the ring's in the slice frame (same volume).
ParticleBox count_box(const Case& c, double periodic_depth) {
    return c.cell.ring() ? ring_slice_box(c) : particle_box(c, periodic_depth);
}

// Where the grains are inserted: below opt.height (the plate's start under load), else below H.
double insertion_height(const Case& c, const InsertionOptions& opt) { return opt.height > 0 ? opt.height : c.cell.gap; }

// The slice's insertion box: the count box up to the insertion height, less the bumps' halves
// (insert_grains places it from y = opt.floor, centred across the width).
ParticleBox insertion_box(const Case& c, const ParticleBox& count, const InsertionOptions& opt) {
    ParticleBox b = count;
    b.gap = insertion_height(c, opt) - opt.floor - opt.ceiling;
    if (!b.periodic_z) b.width -= 2.0 * opt.side;
    return b;
}

// The grain count of a point, checked: the one place both initial_particles() and
// check_initial_particles() take it from.
std::size_t point_grains(const Case& c, const OperatingPoint& pt, const ParticleBox& box, const std::string& fill_key,
                         const InsertionOptions& opt) {
    const GrainSizes g = c.grains.sizes();
    try {
        const std::size_t n = grains_for_fill(box, g, pt.solid_fraction);
        if (!c.cell.ring()) {
            check_fits(insertion_box(c, box, opt), g, n);
        } else if (const std::size_t most = ring_capacity(annulus(c), insertion_height(c, opt), g.max(), opt.wall_sag);
                   most < n) {
            throw CaseError(fmt::format("{} grains do not fit in the ring below {:g} m (where they are inserted); at "
                                        "most {}, a solid fraction of {:.4f} over the gap",
                                        n, insertion_height(c, opt), most,
                                        static_cast<double>(most) * g.mean_volume() / box.volume()));
        }
        return n;
    } catch (const CaseError& e) {
        throw CaseError(fmt::format("{}: point {}: {} = {:g}: {}", c.file.string(), pt.id, fill_key,
                                    pt.solid_fraction, e.what()));
    }
}

InsertionOptions with_case(const Case& c, const OperatingPoint& pt, InsertionOptions opt) {
    opt.wall_speed = pt.speed;
    opt.size_spread = c.grains.size_spread;
    opt.floor = bump_protrusion(c, pt.bottom);
    opt.ceiling = bump_protrusion(c, pt.top);
    opt.side = c.side_walls == SideWalls::AsBottom ? opt.floor : 0.0;  // the floor's bumps (wall_bumps.h)
    return opt;
}
}  // namespace

void check_initial_particles(const Case& c, const OperatingPoint& pt, double periodic_depth,
                             const std::string& fill_key, const InsertionOptions& opt) {
    point_grains(c, pt, count_box(c, periodic_depth), fill_key, with_case(c, pt, opt));
}

InitialParticles initial_particles(const Case& c, const OperatingPoint& pt, const std::filesystem::path& root,
                                   const InsertionOptions& opt_in, double periodic_depth, const std::string& fill_key,
                                   const std::filesystem::path& member) {
    InitialParticles out;
    out.box = count_box(c, periodic_depth);
    out.file = initial_particles_path(root, pt.id);
    if (!member.empty()) out.file = out.file.parent_path() / member / out.file.filename();
    const InsertionOptions opt = with_case(c, pt, opt_in);
    const double d = c.grains.diameter;
    const std::size_t n = point_grains(c, pt, out.box, fill_key, opt);
    std::string key = fmt::format("key: box={:.17g},{:.17g},{:.17g},{} d={:.17g} n={} U={:.17g} noise={:.17g} seed={}",
                                  out.box.length, out.box.gap, out.box.width, out.box.periodic_z ? "pz" : "wz", d, n,
                                  opt.wall_speed, opt.velocity_noise, opt.seed);
    if (c.cell.ring())
        key += fmt::format(" ring R={:.17g} h={:.17g} sag={:.17g}", c.cell.annulus_radius, insertion_height(c, opt),
                           opt.wall_sag);
    else if (opt.height > 0)
        key += fmt::format(" h={:.17g}", opt.height);
    if (opt.size_spread > 0) key += fmt::format(" spread={:.17g}", opt.size_spread);
    if (opt.floor > 0 || opt.ceiling > 0) key += fmt::format(" bumps={:.17g},{:.17g}", opt.floor, opt.ceiling);
    if (opt.side > 0) key += fmt::format(" side_bumps={:.17g}", opt.side);
    if (std::filesystem::exists(out.file)) {
        const auto comments = read_particles_comments(out.file);
        if (std::find(comments.begin(), comments.end(), key) != comments.end()) {
            out.particles = read_particles_csv(out.file);
            if (out.particles.size() == n) {
                out.reused = true;
                return out;
            }
        }
    }
    out.particles = c.cell.ring() ? insert_ring_grains(annulus(c), insertion_height(c, opt), d, n, opt, opt.wall_sag)
                                  : insert_grains(insertion_box(c, out.box, opt), d, n, opt);
    const std::string sizes =
        opt.size_spread > 0 ? fmt::format("mean diameter {:g} m (spread {:g}, uniform in {:g} to {:g} m)", d,
                                          opt.size_spread, c.grains.sizes().min(), c.grains.sizes().max())
                            : fmt::format("diameter {:g} m", d);
    write_particles_csv(
        out.file, out.particles,
        {c.cell.ring() ? fmt::format("granlub {} initial configuration of the whole ring (ring frame, y the axis: "
                                     "lattice of circles, random subset and jitter)",
                                     version())
                       : fmt::format("granlub {} initial configuration (FCC sites, random subset and jitter)", version()),
         fmt::format("case: {} ({}, hash {})", c.name, c.file.string(), c.file_hash), fmt::format("point: {}", pt.id),
         fmt::format("grains: {} of {}, solid fraction {:.6f} over the gap", n, sizes,
                     solid_fraction(out.particles, out.box)),
         key});
    return out;
}

}  // namespace granlub
