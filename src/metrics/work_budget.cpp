#include "rigdesign/metrics/work_budget.hpp"

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::metrics {

void WorkBudget::check_time(double done, double total, const std::string& what) const {
  const double seconds = elapsed();
  if (!(seconds > max_seconds)) return;
  std::string estimate = "no estimate yet: none was finished";
  if (done > 0)
    estimate = "about " + model::format_number(seconds / done * (total - done), 3) +
               " s more at the rate so far";
  throw model::InputError(model::Diagnostic{
      {"(command line)", 0, 0},
      option,
      "reached after " + model::format_number(seconds, 3) + " s with " +
          model::format_number(done, 6) + " of " + model::format_number(total, 6) + " " + what +
          " judged (" + estimate + ")",
      "a larger " + option + ", or a tolerance on fewer axes or mounts"});
}

}  // namespace rigdesign::metrics
