#include "granlub/automaton/vtk.h"
#include "granlub/results/pvd.h"

#include <cmath>

#include <fmt/format.h>

namespace granlub::automaton {

std::string lattice_vti(const Lattice& e, double diameter) {
    const int L = e.columns(), H = e.rows();
    const int ny = H + 2;  // wall rows included
    std::string state, speed, dir, vel;
    state.reserve(static_cast<std::size_t>(L) * ny * 2);
    for (int y = -1; y <= H; ++y)
        for (int x = 0; x < L; ++x) {
            const std::int32_t c = e.cell(x, y);
            int st = 0, d = -1;
            double u = 0, vx = 0, vy = 0;
            if (c == kWallBottom) { st = 2; u = 1; vx = 1; }
            else if (c == kWallTop) { st = 3; }
            else if (c >= 0) {
                st = 1;
                u = e.up(c);
                d = e.dir(c);
                const double norm = (kDx[d] != 0 && kDy[d] != 0) ? std::sqrt(0.5) : 1.0;
                vx = u * kDx[d] * norm;
                vy = u * kDy[d] * norm;
            }
            fmt::format_to(std::back_inserter(state), "{} ", st);
            fmt::format_to(std::back_inserter(speed), "{:.6g} ", u);
            fmt::format_to(std::back_inserter(dir), "{} ", d);
            fmt::format_to(std::back_inserter(vel), "{:.6g} {:.6g} 0 ", vx, vy);
        }
    return fmt::format(
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
        "  <ImageData WholeExtent=\"0 {0} 0 {1} 0 1\" Origin=\"0 {2:.9g} 0\" Spacing=\"{3:.9g} {3:.9g} {3:.9g}\">\n"
        "    <Piece Extent=\"0 {0} 0 {1} 0 1\">\n"
        "      <CellData Scalars=\"state\" Vectors=\"velocity\">\n"
        "        <DataArray type=\"UInt8\" Name=\"state\" format=\"ascii\">{4}</DataArray>\n"
        "        <DataArray type=\"Float32\" Name=\"u_over_U\" format=\"ascii\">{5}</DataArray>\n"
        "        <DataArray type=\"Int8\" Name=\"direction\" format=\"ascii\">{6}</DataArray>\n"
        "        <DataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">{7}</DataArray>\n"
        "      </CellData>\n"
        "    </Piece>\n"
        "  </ImageData>\n"
        "</VTKFile>\n",
        L, ny, -diameter, diameter, state, speed, dir, vel);
}

std::string snapshot_pvd(const std::vector<std::pair<double, std::string>>& files) {
    std::vector<PvdEntry> entries;
    for (const auto& [t, f] : files) entries.push_back({t, 0, f});
    return pvd_collection(entries);  // core's one .pvd writer
}

}  // namespace granlub::automaton
