#pragma once
// Where `granmix hcs`'s first-Sonine numbers should not be trusted (docs/user-guide.md, "granmix hcs": warnings): the
// criteria are computed from the summary's own truncation estimates (the Sonine order 3 beside the first Sonine) and
// are stated with their reasons in hcs_warnings.cpp. A warning does not change the exit code.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace granmix::compare {

struct HcsSummary;

struct HcsWarning {
  std::string code;         // stable: c_large, c_orders_disagree, T_ratio_orders_disagree, sonine3_no_steady_state, non_finite
  std::size_t species = 0;  // 1-based; 0 where the warning concerns the whole mixture
  std::string message;      // one line naming the species, the numbers and the way out
};

// The warnings of a computed summary, in species order.
std::vector<HcsWarning> hcs_warnings(const HcsSummary& h);
nlohmann::ordered_json hcs_warnings_json(const std::vector<HcsWarning>& warnings);

}  // namespace granmix::compare
