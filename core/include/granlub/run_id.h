// The run id: which invocation of granlub wrote a result file. Each file alone is written
// atomically, but two runs on one case could leave a point whose summary.json comes from one run
// and whose profile.csv from the other (issue 34); every file of a point therefore names its run
// (summary.json's provenance.run_id, a "# run_id <id>" comment line in every table) and
// load_result calls a point whose files name different runs corrupt.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace granlub {

// This process's run id, made on first use and the same for the rest of the process (every
// solver and point of one `granlub run`): UTC time, host, pid and 32 random bits, e.g.
// "20261125T101112Z-node7-4242-9f3a01c2". Time and pid make it readable; the random part keeps it
// unique across hosts sharing a results folder and across pid reuse. It is provenance only: no
// computed number depends on it.
const std::string& run_id();

// The comment text that names a run in a table, "run_id <id>"; writers put it on a '#' line.
std::string run_id_comment(std::string_view id = run_id());

// The run named by a table's leading '#' comment lines; nothing when none names one (a table
// written before run ids) or the file cannot be read.
std::optional<std::string> table_run_id(std::string_view text);
std::optional<std::string> read_table_run_id(const std::filesystem::path& file);

}  // namespace granlub
