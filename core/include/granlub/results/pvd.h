// ParaView's collection file (.pvd): a time series of VTK files, one DataSet per (time, part).
// Format as VTK and ParaView write it (type "Collection", version "0.1"; see
// https://www.paraview.org/Wiki/ParaView/Data_formats#PVD_File_Format). Written by the automaton
// (lattice snapshots) and `granlub dem --vtk` (LIGGGHTS' dumps).
#pragma once
#include <string>
#include <vector>

namespace granlub {

struct PvdEntry {
    double time = 0;    // s
    int part = 0;       // several files at one time: 0, 1, ...
    std::string file;   // relative to the .pvd
};

// The .pvd text; times with the shortest exact decimal form.
std::string pvd_collection(const std::vector<PvdEntry>& entries);

}  // namespace granlub
