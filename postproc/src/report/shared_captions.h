// No caption sentence said more than twice: a sentence that three or more captions of the report
// share (the critical shear rate's line, the fitted power law, the lattice solver not drawn) leaves
// those captions and is said once in each part (level-2 heading) that had it, above its figures,
// as "Figures below: ...". The figure files keep their full captions.
#pragma once
#include <string>
#include <vector>

#include "formats/report.h"

namespace granlub::postproc {

// A caption's sentences: it breaks after ". " where the next word does not start with a lower-case
// letter or a digit ("p. 3", "0.5 m/s" stay whole); each sentence keeps its full stop.
std::vector<std::string> caption_sentences(const std::string& caption);

void say_shared_captions_once(Report& rep);

}  // namespace granlub::postproc
