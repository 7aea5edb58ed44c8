#include "report/paraview.h"

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyLine.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include "figures/figures.h"
#include "figures/cross_section_map.h"
#include "granlub/error.h"

namespace granlub::postproc {
namespace {

void add_array(vtkPolyData* pd, const std::string& name, const std::vector<double>& v) {
    if (v.empty()) return;
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->SetNumberOfValues(static_cast<vtkIdType>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), v[i]);
    pd->GetPointData()->AddArray(a);
}

vtkSmartPointer<vtkPolyData> profile_polydata(const Run& r, double gap) {
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    const auto& y = r.y();
    vtkNew<vtkPoints> pts;
    vtkNew<vtkPolyLine> line;
    line->GetPointIds()->SetNumberOfIds(static_cast<vtkIdType>(y.size()));
    for (std::size_t i = 0; i < y.size(); ++i) {
        pts->InsertNextPoint(0.0, y[i] * gap, 0.0);
        line->GetPointIds()->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
    }
    vtkNew<vtkCellArray> cells;
    cells->InsertNextCell(line);
    pd->SetPoints(pts);
    pd->SetLines(cells);
    // Every column of the profile as written by the solver, then the normalised comparison columns.
    const Profile& p = *r.profile;
    for (std::size_t k = 0; k < p.names.size(); ++k) add_array(pd, p.names[k], p.columns[k]);
    add_array(pd, "nu_over_numax", r.column("nu_over_numax"));
    add_array(pd, "nu_over_numax_stderr", r.column_stderr("nu_over_numax"));
    std::vector<double> u = r.column("u_over_U");
    for (double& v : u) v *= r.point->speed;
    add_array(pd, "u", u);
    vtkNew<vtkStringArray> solver;
    solver->SetName("solver");
    solver->InsertNextValue(r.solver);
    pd->GetFieldData()->AddArray(solver);
    vtkNew<vtkDoubleArray> speed;
    speed->SetName("U");
    speed->InsertNextValue(r.point->speed);
    pd->GetFieldData()->AddArray(speed);
    return pd;
}

// The cross-section (section.csv) as an image of 1 x ny x nz cells over y in [0, gap] and
// z in [-width/2, width/2], cell data solid_fraction and u_over_U.
vtkSmartPointer<vtkImageData> cross_section_image(const CrossSectionMap& m, double gap, double width) {
    auto im = vtkSmartPointer<vtkImageData>::New();
    im->SetDimensions(2, static_cast<int>(m.ny) + 1, static_cast<int>(m.nz) + 1);
    im->SetOrigin(0.0, 0.0, -0.5 * width);
    im->SetSpacing(gap / static_cast<double>(m.ny), gap / static_cast<double>(m.ny), width / static_cast<double>(m.nz));
    for (const auto& [name, v] : {std::pair<const char*, const std::vector<double>*>{"solid_fraction", &m.nu},
                                  {"u_over_U", &m.u}}) {
        vtkNew<vtkDoubleArray> a;
        a->SetName(name);
        a->SetNumberOfValues(static_cast<vtkIdType>(v->size()));
        for (std::size_t c = 0; c < v->size(); ++c) {  // ours: z fastest; VTK's: x, then y, then z
            const std::size_t k = c / m.nz, l = c % m.nz;
            a->SetValue(static_cast<vtkIdType>(k + m.ny * l), (*v)[c]);
        }
        im->GetCellData()->AddArray(a);
    }
    return im;
}

}  // namespace

std::vector<std::filesystem::path> write_paraview(const Collection& col, double gap, double width,
                                                  const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> written;
    std::filesystem::create_directories(dir);
    for (const OperatingPoint* p : col.points) {
        const auto runs = col.usable(p->id);
        if (runs.empty()) continue;
        vtkNew<vtkMultiBlockDataSet> mb;
        unsigned block = 0;
        for (const Run* r : runs) {
            mb->SetBlock(block, profile_polydata(*r, gap));
            mb->GetMetaData(block++)->Set(vtkCompositeDataSet::NAME(), r->solver.c_str());
        }
        for (const Run* r : runs)  // the cross-sections (y x z) of the particle runs and the continuum, where written
            if (const auto m = read_cross_section(*r); m && width > 0) {
                mb->SetBlock(block, cross_section_image(*m, gap, width));
                mb->GetMetaData(block++)->Set(vtkCompositeDataSet::NAME(), (r->solver + " cross-section").c_str());
            }
        const auto file = dir / (point_slug(*p) + ".vtm");
        vtkNew<vtkXMLMultiBlockDataWriter> w;
        w->SetFileName(file.string().c_str());
        w->SetInputData(mb);
        w->SetDataModeToAscii();
        if (w->Write() != 1) throw Error(fmt::format("{}: VTK could not write the ParaView file", file.string()));
        written.push_back(file);
    }
    return written;
}

}  // namespace granlub::postproc
