// Results of a load-controlled particle run, engine-independent (load_control.h).
#include "granlub/particles/load_control.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "granlub/results/run_id.h"

namespace granlub {

BlockEstimate mean_gap(const PlateSeries& plate, const SteadyWindow& w, std::size_t blocks) {
    return block_average(std::span<const double>(plate.gap).subspan(w.plate_start), blocks);
}

std::vector<double> window_stresses(const ServoSettings& s, std::span<const double> wall_step,
                                    std::span<const double> top_stress, const PlateSeries& plate) {
    std::vector<double> out;
    std::size_t i = 0;
    for (std::size_t j = 0; j < plate.step.size(); ++j) {
        double sum = 0;
        std::size_t n = 0;
        while (i < wall_step.size() && wall_step[i] <= plate.step[j] + 0.5) {
            if (wall_step[i] > plate.step[j] - static_cast<double>(s.servo_every) + 0.5) {
                sum += top_stress[i];
                ++n;
            }
            ++i;
        }
        out.push_back(n > 0 ? sum / static_cast<double>(n) : -1.0);
    }
    return out;
}

std::string gap_csv(const ServoSettings& s, double time_step, std::span<const double> wall_step,
                    std::span<const double> top_stress, const PlateSeries& plate, const std::string& comment) {
    const std::vector<double> p_w = window_stresses(s, wall_step, top_stress, plate);
    std::string out = fmt::format("# {}\n# plate (top wall{}) position after each {} of {} steps; stress = "
                                  "top-wall normal stress averaged over the window; target {} Pa\n# {}\n"
                                  "time_s,gap_m,normal_stress_top_Pa\n",
                                  comment, s.weight_plate ? ", a weighted plate" : "",
                                  s.weight_plate ? "window" : "servo window", s.servo_every, s.target_stress,
                                  run_id_comment());
    for (std::size_t j = 0; j < plate.step.size(); ++j)
        out += fmt::format("{},{},{}\n", plate.step[j] * time_step, plate.gap[j],
                           p_w[j] >= 0 ? fmt::format("{}", p_w[j]) : std::string(""));
    return out;
}

nlohmann::json load_summary(const LoadSummaryInputs& in, std::map<std::string, Scalar>& outputs, std::string& line) {
    const ServoSettings& s = in.servo;
    const PlateSeries& plate = in.plate;
    const BlockEstimate g = mean_gap(plate, in.window, in.blocks);
    const double nu = in.solids_volume / (in.area * g.mean);
    outputs["gap"] = Scalar{g.mean, g.stderr_, "m"};
    outputs["mean_solid_fraction"] = Scalar{nu, nu * g.stderr_ / g.mean, ""};
    const Scalar& top = outputs.at("normal_stress_top");
    auto at_a_limit = [&](double h) { return h <= s.gap_min * (1 + 1e-9) || h >= s.gap_max * (1 - 1e-9); };
    const auto at_limit = static_cast<std::size_t>(std::count_if(plate.gap.begin(), plate.gap.end(), at_a_limit));
    const bool limit_now = at_a_limit(plate.gap.back());
    line = fmt::format(" gap={:.4g} mm (P_top/P={:.3f}{})", 1e3 * g.mean, top.value / s.target_stress,
                       limit_now ? ", PLATE AT ITS LIMIT: target not reachable" : "");
    nlohmann::json j = {{"target_normal_stress_Pa", s.target_stress},
            {"plate", s.weight_plate ? "weight" : "window"},
            {"normal_stress_top_over_target", top.value / s.target_stress},
            {"deviation_in_stderr",  // 0 when there is no error bar (never inf/NaN in a result)
             top.stderr_.value_or(0) > 0 ? (top.value - s.target_stress) / *top.stderr_ : 0.0},
            {"gap_initial_m", in.initial_gap},
            {"gap_mean_m", g.mean},
            {"gap_stderr_m", g.stderr_},
            {"gap_final_m", plate.gap.back()},
            {"servo_updates", plate.gap.size()},
            {"servo_updates_used", plate.gap.size() - in.window.plate_start},
            {"updates_at_plate_limit", at_limit},
            {"plate_at_limit_at_end", limit_now},
            {"gap_file", kGapFile}};
    if (!s.weight_plate) {  // the window servo's windows whose stress error hit the upper clamp (a weight has none)
        std::size_t clamped = 0;
        for (double pw : window_stresses(s, in.wall_step, in.top_stress, plate))
            if (pw > (1.0 + s.servo_max_error) * s.target_stress) ++clamped;
        j["updates_error_clamped"] = clamped;
    }
    return j;
}

}  // namespace granlub
