#include "paraview.h"

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
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

#include "figures.h"
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

}  // namespace

std::vector<std::filesystem::path> write_paraview(const Collection& col, double gap, const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> written;
    std::filesystem::create_directories(dir);
    for (const OperatingPoint* p : col.points) {
        const auto runs = col.usable(p->id);
        if (runs.empty()) continue;
        vtkNew<vtkMultiBlockDataSet> mb;
        mb->SetNumberOfBlocks(static_cast<unsigned>(runs.size()));
        for (std::size_t b = 0; b < runs.size(); ++b) {
            const auto block = static_cast<unsigned>(b);
            mb->SetBlock(block, profile_polydata(*runs[b], gap));
            mb->GetMetaData(block)->Set(vtkCompositeDataSet::NAME(), runs[b]->solver.c_str());
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
