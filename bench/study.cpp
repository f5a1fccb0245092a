#include <stdexcept>

#include "study.hpp"

namespace granmix::bench {

const std::vector<std::string>& study_names() {
  static const std::vector<std::string> names = {"selectors", "theory", "dsmc-error", "methods", "gaps", "checkpoint", "schedule"};
  return names;
}

StudyResult run_study(const std::string& name, const StudyOptions& o) {
  if (name == "selectors") return selectors_study(o);
  if (name == "theory") return theory_study(o);
  if (name == "dsmc-error") return dsmc_error_study(o);
  if (name == "methods") return methods_study(o);
  if (name == "gaps") return gaps_study(o);
  if (name == "schedule") return schedule_study(o);
  if (name == "checkpoint") return checkpoint_study(o);
  throw std::invalid_argument("bench: unknown study '" + name + "'");
}

}  // namespace granmix::bench
