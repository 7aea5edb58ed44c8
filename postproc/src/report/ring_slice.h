// The whole ring against its slice ([report] slice_case): granlub dem's results of a ring case
// ([cell] geometry = "annulus") beside those of a slice case at the same point ids. Both are
// written in the slice's frame (core granlub/particles/annulus.h), so they compare column by column; the
// width profile shows what the slice's centripetal body force stands in for.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "formats/figure_model.h"
#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

// The solver that runs the whole ring, as its declaration says (SolverInfo::whole_ring, carried by
// its case section); empty when no solver built in does.
std::string ring_solver(const Case& c);

struct RingSlicePart {
    std::string slice_case;          // as [report] slice_case gives it
    std::string solver;              // ring_solver(): whose results are set side by side
    std::vector<std::string> notes;  // what could not be compared, and why
    Table table;                     // per point and quantity: ring, slice, difference in standard errors
    std::vector<Figure> figures;     // per compared point: across the width and across the gap
};

// Nothing to show (no slice_case): an empty part with an empty slice_case. A slice case that
// cannot be read, or points without steady results on both sides, are notes, not errors: the
// rest of the report stands.
RingSlicePart ring_slice_part(const Case& ring, const Collection& col);

// The slice case whose results (its default folder) ring_slice_part reads, when [report] slice_case
// names a case that loads: compare holds its dem points locked (shared) while it reads them.
std::optional<Case> slice_case(const Case& ring);

}  // namespace granlub::postproc
