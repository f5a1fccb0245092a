// granmix hcs as users run it, both forms (masses/diameters/densities and MG's μ, δ, w, α) and --json: its fields
// against the in-process solvers, closed forms (Chapman–Cowling's 59/58), its messages, and its warnings where the
// first Sonine breaks down (compare/hcs_warnings.hpp) (split from test_commands.cpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/hcs_summary.hpp"
#include "granmix_version.hpp"
#include "model/enskog.hpp"
#include "run_cli.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory/sonine/sonine2_diffusion.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_second_order.hpp"

using namespace granmix;

TEST_CASE("granmix hcs --json: fields of docs/architecture.md §3 in input order", "[compare]") {
  const auto r = test::run_granmix("hcs --mass 1,100 --diameter 1,4.6416 --density 0.1,0.1 --eps 0.5 --json");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.output);
  REQUIRE(j["species"].size() == 2);
  CHECK(j["species"][0]["T_ratio_maxwell"].get<double>() == 1.0);
  const model::Mixture mix({{1, 1, 0.1}, {100, 4.6416, 0.1}});
  const theory::CollisionRates rates(mix, model::Restitution::constant(2, 0.5), model::dilute_contact_values(2));
  const auto d = theory::settled_diffusion(rates);
  CHECK(j["species"][1]["T_ratio_maxwell"].get<double>() == Approx(d.T[1] / d.T[0]).epsilon(1e-14));
  CHECK(j["species"][1]["D_ratio"].get<double>() == Approx(d.D_ratio[1]).epsilon(1e-14));
  CHECK(j["tau0"].get<double>() == Approx(d.tau0).epsilon(1e-14));
  // First-Sonine fields (MG App. A) for the same mixture, computed in-process.
  const auto sonine = theory::sonine_hcs(mix, model::Restitution::constant(2, 0.5), model::dilute_contact_values(2));
  CHECK(j["species"][1]["T_ratio_sonine"].get<double>() == Approx(sonine.T[1] / sonine.T[0]).epsilon(1e-14));
  CHECK(j["species"][0]["c"].get<double>() == Approx(sonine.c[0]).epsilon(1e-14));
  CHECK(j["zeta_star"].get<double>() == Approx(sonine.zeta_star).epsilon(1e-14));
  // Keys in the order of docs/architecture.md §3 (extensions after them).
  const auto ordered = nlohmann::ordered_json::parse(r.output);
  std::vector<std::string> keys;
  for (const auto& item : ordered["species"][0].items()) keys.push_back(item.key());
  CHECK(keys == std::vector<std::string>{"T_ratio_maxwell", "T_ratio_sonine", "c", "D_ratio", "tail_exponent", "D_sonine2_factor", "D_sonine_factors",
                                         "D_converged_factor", "D_converged_change", "T_ratio_sonine3", "c_sonine3", "a3_sonine3"});
  // Sonine order 3 (the level kinetic-cooling3's HCS), computed in-process.
  const auto third = theory::sonine_hcs(mix, model::Restitution::constant(2, 0.5), model::dilute_contact_values(2), false,
                                        theory::SonineSolver::automatic, 3);
  CHECK(j["species"][1]["T_ratio_sonine3"].get<double>() == Approx(third.T[1] / third.T[0]).epsilon(1e-14));
  CHECK(j["species"][0]["c_sonine3"].get<double>() == Approx(third.c[0]).epsilon(1e-14));
  CHECK(j["species"][0]["a3_sonine3"].get<double>() == Approx(third.a3[0]).epsilon(1e-14));
  CHECK(j["zeta_star_sonine3"].get<double>() == Approx(third.zeta_star).epsilon(1e-14));
  // Second-Sonine factor D_k[2]/D_k[1] at the settled ratios, computed in-process (0.9209 for the light species).
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(j["species"][k]["D_sonine2_factor"].get<double>() == Approx(theory::sonine_factor(rates, k, d.T.data(), 2)).epsilon(1e-14));
    // Orders 1 … 5: order 1 is 1, order 2 the factor above (the light species converges alternating to ~0.935).
    const auto orders = j["species"][k]["D_sonine_factors"].get<std::vector<double>>();
    REQUIRE(orders.size() == theory::max_sonine_modes);
    CHECK(orders[0] == 1.0);
    CHECK(orders[1] == j["species"][k]["D_sonine2_factor"].get<double>());
    for (std::size_t M = 1; M <= orders.size(); ++M) CHECK(orders[M - 1] == Approx(theory::sonine_factor(rates, k, d.T.data(), M)).epsilon(1e-14));
    // The same problem converged (tracer_diffusion_galerkin.hpp), computed in-process: within the light species'
    // alternating orders 4 and 5 (0.9317, 0.9366), and its truncation left far below their step.
    CHECK(j["species"][k]["D_converged_factor"].get<double>() == Approx(theory::converged_tracer_diffusion(rates, k, d.T.data()).factor).epsilon(1e-14));
    CHECK(j["species"][k]["D_converged_change"].get<double>() < 0.1 * std::abs(orders[4] - orders[3]));
  }
  const auto light = j["species"][0]["D_sonine_factors"].get<std::vector<double>>();
  CHECK(j["species"][0]["D_converged_factor"].get<double>() > std::min(light[3], light[4]));
  CHECK(j["species"][0]["D_converged_factor"].get<double>() < std::max(light[3], light[4]));
}

TEST_CASE("granmix hcs: D_sonine2_factor of elastic hard spheres is 59/58 (Chapman-Cowling second approximation)", "[compare]") {
  const auto r = test::run_granmix("hcs --mass 2 --diameter 1 --density 0.3 --eps 1 --json");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK(nlohmann::json::parse(r.output)["species"][0]["D_sonine2_factor"].get<double>() == Approx(59.0 / 58).epsilon(1e-14));
  // No exponential tail without dissipation (2β/ζ* = ∞): the key is left out, never written as null.
  CHECK_FALSE(nlohmann::json::parse(r.output)["species"][0].contains("tail_exponent"));
  CHECK(r.output.find("null") == std::string::npos);
  const auto text = test::run_granmix("hcs --mass 2 --diameter 1 --density 0.3 --eps 1");
  CHECK(text.output.find("D_sonine2_factor") != std::string::npos);
  CHECK(text.output.find("1.0172414") != std::string::npos);  // 59/58 = 1.01724138 to the column's 8 digits
}

TEST_CASE("granmix hcs: second-Sonine a2 and a3 of one species - and the one-species truncation object of a mixture", "[compare]") {
  const auto one = test::run_granmix("hcs --mass 2 --diameter 1 --density 0.3 --eps 0.5 --json");
  INFO(one.output);
  REQUIRE(one.code == 0);
  const auto j = nlohmann::json::parse(one.output);
  const theory::SecondSonine s = theory::second_sonine_hcs(0.5);
  CHECK(j["species"][0]["a2_sonine2"].get<double>() == Approx(s.a2).epsilon(1e-14));
  CHECK(j["species"][0]["a3_sonine2"].get<double>() == Approx(s.a3).epsilon(1e-14));
  CHECK(j["species"][0]["c"].get<double>() / 2 != Approx(s.a2).epsilon(0.1));  // a₂[1] = 0.0525, a₂[2] = 0.0450
  CHECK(!j.contains("one_species_truncation"));
  // MG form with one alpha: the top-level proxy object; with per-pair alphas: none.
  const auto mg = nlohmann::json::parse(test::run_granmix("hcs --mu 4 --delta 0.5 --w 1 --alpha 0.5 --json").output);
  REQUIRE(mg.contains("one_species_truncation"));
  const auto& t = mg["one_species_truncation"];
  CHECK(t["eps"].get<double>() == 0.5);
  CHECK(t["a2_sonine2"].get<double>() == Approx(s.a2).epsilon(1e-14));
  CHECK(t["a2_sonine1"].get<double>() == Approx(0.5 * j["species"][0]["c"].get<double>()).epsilon(1e-14));
  CHECK(t["a2_relative_change"].get<double>() == Approx(std::abs(s.a2 / t["a2_sonine1"].get<double>() - 1)).epsilon(1e-14));
  CHECK(!mg["species"][0].contains("a2_sonine2"));
  const auto pairs = nlohmann::json::parse(test::run_granmix("hcs --mu 4 --delta 0.5 --w 1 --alpha11 0.5 --alpha22 0.5 --alpha12 0.5 --json").output);
  CHECK(!pairs.contains("one_species_truncation"));
  const auto text = test::run_granmix("hcs --mu 4 --delta 0.5 --w 1 --alpha 0.5");
  CHECK(text.output.find("one-species proxy") != std::string::npos);
}

TEST_CASE("granmix hcs: v2 Fig. 5's intruder temperature converged - the Monte Carlo's, not the Sonine's", "[compare]") {
  // At the Santos–Dufty edge (m₂/m₁ = 100, ε = 0.5) the speed grid's θ against scripts/tracer_intruder_mc.cpp's 638.84 ±
  // 0.64 (the gas's first-Sonine shape and rate, 1e6 time units); the first Sonine's 504.6 is 200 σ off.
  const auto r = test::run_granmix("hcs --mass 1,100 --diameter 1,4.641588833612779 --density 0.1,0.00001 --eps 0.5 --json");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.output)["species"][1];
  CHECK(std::abs(j["T_ratio_tracer_converged"].get<double>() - 638.84) < 4.0 * 0.64);
  CHECK(j["T_ratio_tracer_converged_change"].get<double>() < 1e-2);
  // At its own density its heating of the gas included: the Monte Carlo's self-consistent 580.0 ± 0.6 (DSMC ≈ 570).
  CHECK(std::abs(j["T_ratio_intruder_converged"].get<double>() - 580.0) < 4.0 * 0.6);
  CHECK(j["xi12_intruder_converged"].get<double>() < 0.0);
  const auto text = test::run_granmix("hcs --mass 1,100 --diameter 1,4.641588833612779 --density 0.1,0.00001 --eps 0.5");
  // The text carries the JSON's number to its 10 digits.
  char line[64];
  std::snprintf(line, sizeof line, "converged: T_ratio %.10g", j["T_ratio_tracer_converged"].get<double>());
  CHECK(text.output.find(line) != std::string::npos);
}

TEST_CASE("granmix hcs - MG form: gamma of MG Fig. 1 at the Maxwellian level", "[compare]") {
  const auto r = test::run_granmix("hcs --mu 10 --delta 2 --w 1 --alpha 0.5 --json");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.output);
  const double gamma = 1.0 / j["species"][1]["T_ratio_maxwell"].get<double>();  // γ = T1/T2
  CHECK(gamma == Approx(3.8).margin(0.05));  // MG Fig. 1: γ ≃ 3.8 (two published digits)
  const double gamma_sonine = 1.0 / j["species"][1]["T_ratio_sonine"].get<double>();
  CHECK(gamma_sonine == Approx(3.8).margin(0.01));  // first Sonine: 3.8005
  CHECK(!j.contains("tau0"));  // dilute MG form has no absolute density
  const auto text = test::run_granmix("hcs --mu 10 --delta 2 --w 1 --alpha 0.5");
  CHECK(text.code == 0);
  CHECK(text.output.find("T_ratio_maxwell") != std::string::npos);
}

TEST_CASE("granmix hcs: bad usage exits 2 with a message", "[compare]") {
  for (const char* args : {"hcs --mass 1,100 --diameter 1 --density 0.1,0.1 --eps 0.5", "hcs --mu 10 --delta 2 --w 1 --alpha 1.5",
                           "hcs --mass 1 --diameter 1 --density 0.1 --eps 0.5 --mu 2", "hcs --mass 1,x", "hcs --eps 0.5", ""}) {
    const auto r = test::run_granmix(args);
    INFO(args << " -> " << r.output);
    CHECK(r.code == 2);
    CHECK(!r.output.empty());
  }
}

TEST_CASE("granmix hcs --converged: the HCS without the Sonine truncation against MG Fig. 5's DSMC", "[compare]") {
  // μ = 4, δ = 0.25, α = 0.5: the point where the first Sonine misses DSMC most (γ −0.43%; DSMC 2.38897, the mean of
  // three paper seeds, σ ≈ 0.1%); the converged γ is within 0.3%, its own error estimate below 0.1%, and the cumulant
  // of species 1 about 10% below the first Sonine's (DSMC: 9–15% below at α ≤ 0.5, MG Fig. 2).
  const auto r = test::run_granmix("hcs --mu 4 --delta 0.25 --w 1 --alpha 0.5 --json --converged");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.output);
  const auto& s2 = j["species"][1];
  const double gamma = 1.0 / s2["T_ratio_converged"].get<double>();
  CHECK(std::abs(gamma / 2.38897 - 1.0) < 0.003);
  CHECK(std::abs(1.0 / s2["T_ratio_sonine"].get<double>() / 2.38897 - 1.0) > 0.004);  // the first Sonine does not meet it
  CHECK(j["converged_error"]["T_ratio"].get<double>() < 1e-3);
  const double c1 = j["species"][0]["c_converged"].get<double>(), c1_sonine = j["species"][0]["c"].get<double>();
  CHECK(c1 / c1_sonine < 0.95);
  CHECK(c1 / c1_sonine > 0.80);
  CHECK(j["zeta_star_converged"].get<double>() > 0.0);
  const auto many = test::run_granmix("hcs --mass 1,2,3,4,5,6,7,8,9,10,11 --diameter 1,1,1,1,1,1,1,1,1,1,1 --density 1,1,1,1,1,1,1,1,1,1,1 --eps 0.5 --converged");
  CHECK(many.code == 2);
  CHECK(many.output.find("--converged: at most 10 species") != std::string::npos);
}

namespace {

// The codes of `granmix hcs --json`'s warnings, each as "code:species" (species 0: the whole mixture).
std::vector<std::string> hcs_warning_codes(const nlohmann::json& j) {
  std::vector<std::string> codes;
  for (const auto& w : j.at("warnings")) codes.push_back(w.at("code").get<std::string>() + ":" + std::to_string(w.value("species", 0)));
  return codes;
}

bool lists_code(const std::vector<std::string>& codes, const std::string& code) {
  return std::find(codes.begin(), codes.end(), code) != codes.end();
}

}  // namespace

TEST_CASE("granmix hcs warns where the first Sonine breaks down: masses 1:1000 at n2 = 1e-4", "[compare]") {
  // c₁ = 1.69 at first Sonine, 0.54 at order 3 (the converged HCS: 1.20 ± 0.35): c_large and c_orders_disagree for
  // species 1; T₂/T₁ 3042 against 2706 at order 3 (11%): T_ratio_orders_disagree for species 2.
  const std::string args = "hcs --mass 1,1000 --diameter 1,10 --density 0.1,1e-4 --eps 0.5";
  const auto r = test::run_granmix(args + " --json");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.output);
  const auto codes = hcs_warning_codes(j);
  CHECK(lists_code(codes, "c_large:1"));
  CHECK(lists_code(codes, "c_orders_disagree:1"));
  CHECK(lists_code(codes, "T_ratio_orders_disagree:2"));
  CHECK_FALSE(lists_code(codes, "c_large:2"));  // c₂ = −0.44: within the bound
  for (const auto& w : j["warnings"]) CHECK(w["message"].get<std::string>().find("--converged") != std::string::npos);
  // The criteria's numbers are the summary's own: c and c_sonine3 as printed beside them.
  const auto& s1 = j["species"][0];
  CHECK(std::abs(s1["c"].get<double>()) > 0.5);
  CHECK(std::abs(s1["c"].get<double>() - s1["c_sonine3"].get<double>()) > 0.2);
  // The text form: the table on stdout as before, one line per warning on stderr naming code, species and numbers.
  const auto text = test::run_granmix_split(args);
  INFO(text.error);
  CHECK(text.code == 0);
  CHECK(text.output.find("T_ratio_sonine") != std::string::npos);
  CHECK(text.output.find("warning") == std::string::npos);
  CHECK(text.error.find("granmix: warning: hcs [c_large] species 1: c = 1.685 at first Sonine") != std::string::npos);
  CHECK(text.error.find("[c_orders_disagree] species 1: c = 1.685 at first Sonine, 0.5374 at Sonine order 3") != std::string::npos);
  CHECK(text.error.find("[T_ratio_orders_disagree] species 2") != std::string::npos);
  CHECK(std::count(text.error.begin(), text.error.end(), '\n') == static_cast<long>(codes.size()));
  // With --converged the warnings point at the converged fields instead.
  const auto conv = nlohmann::json::parse(test::run_granmix(args + " --json --converged").output);
  REQUIRE(!conv["warnings"].empty());
  CHECK(conv["warnings"][0]["message"].get<std::string>().find("c_converged") != std::string::npos);
}

TEST_CASE("granmix hcs warns where the first Sonine breaks down: masses 1:1e6 at eps = 0.01", "[compare]") {
  // T₂/T₁ = 1.1e7 at first Sonine with c₁ = 7.7; order 3 puts T₂/T₁ at 6.0e6 and c₁ at −1.2.
  const auto r = test::run_granmix("hcs --mass 1,1e6 --diameter 1,100 --density 0.1,1e-6 --eps 0.01 --json");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.output);
  CHECK(j["species"][1]["T_ratio_sonine"].get<double>() == Approx(1.1e7).epsilon(0.02));
  const auto codes = hcs_warning_codes(j);
  CHECK(lists_code(codes, "c_large:1"));
  CHECK(lists_code(codes, "c_orders_disagree:1"));
  CHECK(lists_code(codes, "T_ratio_orders_disagree:2"));
  const auto text = test::run_granmix_split("hcs --mass 1,1e6 --diameter 1,100 --density 0.1,1e-6 --eps 0.01");
  CHECK(text.code == 0);
  CHECK(text.error.find("[T_ratio_orders_disagree] species 2: T_ratio_sonine = 1.1") != std::string::npos);
}

TEST_CASE("granmix hcs: the order-3 closure without a steady shape is a warning, not a failure", "[compare]") {
  // Masses 1:1e6 of equal size at n₂/n₁ = 1e-3 … 1e-4: T_max/T_min ~ 1e13, where the order-3 linear system is singular.
  const auto r = test::run_granmix("hcs --mass 1,1e6 --diameter 1,1 --density 0.1,1e-4 --eps 0.01 --json");
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.output);
  CHECK(lists_code(hcs_warning_codes(j), "sonine3_no_steady_state:0"));
  CHECK(!j.contains("zeta_star_sonine3"));
  CHECK(!j["species"][0].contains("c_sonine3"));
}

TEST_CASE("granmix hcs: no warning for the paper systems, nor for one species at any restitution", "[compare]") {
  // Equal-size binaries with mass ratios up to 10 and ε ≥ 0.5 (MG Figs. 1–7), v1's binaries and mixtures at ε = 0.5
  // (Figs. 1–3, 6, 7): their first Sonine is what DSMC confirms (docs/physics.md §6).
  for (const char* args : {"--mu 10 --delta 2 --w 1 --alpha 0.5", "--mu 2 --delta 1 --w 1 --alpha 0.5", "--mu 4 --delta 0.5 --w 1 --alpha 0.5",
                           "--mu 0.1 --delta 2 --w 1 --alpha 0.5", "--mu 4 --delta 0.25 --w 1 --alpha 0.5", "--mu 4 --delta 4 --w 1 --alpha 0.8",
                           "--mu 2 --delta 0.5 --w 2 --alpha 0.6", "--mu 4 --delta 0.5 --w 1 --alpha 0.3", "--mu 10 --delta 2 --w 1 --alpha 0.9",
                           "--mass 1,100 --diameter 1,1 --density 0.1,0.1 --eps 0.5",
                           "--mass 1,100 --diameter 1,4.641588833612779 --density 0.1,0.1 --eps 0.5",
                           "--mass 1,100 --diameter 1,4.641588833612779 --density 0.1,0.001 --eps 0.5",
                           "--mass 1,100,500 --diameter 1,4.641588833612779,7.937005259840998 --density 0.1,0.1,0.1 --eps 0.5",
                           "--mass 1,2,3,4 --diameter 1,1.2599210498948732,1.4422495703074083,1.5874010519681994 --density 0.1,0.1,0.1,0.1 --eps 0.5"}) {
    const auto r = test::run_granmix(std::string("hcs ") + args + " --json");
    INFO(args << " -> " << r.output);
    REQUIRE(r.code == 0);
    CHECK(nlohmann::json::parse(r.output)["warnings"].empty());
    const auto text = test::run_granmix_split(std::string("hcs ") + args);
    CHECK(text.error.empty());
  }
  // One species at ε = 0, the largest cumulant a single species has: van Noije–Ernst's c = 32/81 (closed form) and
  // Brilliantov–Pöschel's second Sonine c = 0.24 (|Δc| = 0.15): both below the bounds 0.5 and 0.2.
  const auto one = nlohmann::json::parse(test::run_granmix("hcs --mass 1 --diameter 1 --density 0.1 --eps 0 --json").output);
  CHECK(one["species"][0]["c"].get<double>() == Approx(32.0 / 81).epsilon(1e-12));
  CHECK(one["warnings"].empty());
}

TEST_CASE("granmix hcs: a missing required flag says so, exit 2, nothing on stdout", "[compare]") {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"hcs --mass 1,2 --diameter 1,1 --density 0.1,0.1", "hcs: --eps is required (or give the MG form --mu --delta --w --alpha)"},
      {"hcs --mass 1,2 --diameter 1,1 --density 0.1,0.1 --json", "hcs: --eps is required"},
      {"hcs --mass 1,2 --density 0.1,0.1 --eps 0.5", "hcs: --mass, --diameter and --density are required"},
      {"hcs --mu 2 --delta 1 --w 1", "hcs: --alpha is required"},
      {"hcs --mu 2 --w 1 --alpha 0.5", "hcs: --mu, --delta and --w are all required in the MG form"},
      {"hcs --mu 2 --delta 1 --w 1 --alpha11 0.5 --alpha22 0.5", "hcs: --alpha11, --alpha22 and --alpha12 are all required"}};
  for (const auto& [args, message] : cases) {
    const auto r = test::run_granmix_split(args);
    INFO(args << " -> " << r.error);
    CHECK(r.code == 2);
    CHECK(r.output.empty());
    CHECK(r.error.find(message) != std::string::npos);
  }
  // A value given out of range keeps its range message.
  CHECK(test::run_granmix_split("hcs --mass 1,2 --diameter 1,1 --density 0.1,0.1 --eps -0.5").error.find("--eps must lie in [0, 1]") !=
        std::string::npos);
}

TEST_CASE("granmix hcs --json echoes its inputs and the version", "[compare]") {
  const auto j = nlohmann::json::parse(test::run_granmix("hcs --mass 1,4 --diameter 1,1.5 --density 0.1,0.05 --eps 0.8 --nstar 0.1 --json").output);
  const auto& in = j["inputs"];
  CHECK(in["mass"] == nlohmann::json::array({1.0, 4.0}));
  CHECK(in["diameter"] == nlohmann::json::array({1.0, 1.5}));
  CHECK(in["density"] == nlohmann::json::array({0.1, 0.05}));
  CHECK(in["eps"].get<double>() == 0.8);
  CHECK(in["nstar"].get<double>() == 0.1);
  CHECK(in["converged"].get<bool>() == false);
  CHECK(!in.contains("mu"));
  CHECK(j["version"].get<std::string>() == granmix::version);
  CHECK(j["git_sha"].get<std::string>() == granmix::git_sha);
  CHECK(j["warnings"].is_array());
  const auto mg = nlohmann::json::parse(test::run_granmix("hcs --mu 2 --delta 1 --w 1 --alpha11 0.9 --alpha22 0.7 --alpha12 0.8 --json").output)["inputs"];
  CHECK(mg["mu"].get<double>() == 2.0);
  CHECK(mg["alpha12"].get<double>() == 0.8);
  CHECK(!mg.contains("alpha"));
  CHECK(!mg.contains("mass"));
}

TEST_CASE("granmix hcs --help lists the output fields and the warning codes", "[compare]") {
  const auto r = test::run_granmix("hcs --help");
  CHECK(r.code == 0);
  for (const char* field : {"T_ratio_sonine", "D_sonine2_factor", "zeta_star", "one_species_truncation", "converged_error", "warnings", "inputs",
                            "version", "c_large", "T_ratio_orders_disagree", "docs/user-guide.md"})
    CHECK(r.output.find(field) != std::string::npos);
}

TEST_CASE("granmix hcs: a non-finite first-Sonine field is a warning of its own, and trips no other", "[compare]") {
  // MG Fig. 1's mixture (no warning) with its c₂ and ζ* replaced by NaN, as a broken solve would leave them.
  compare::HcsOptions o;
  o.mu = 10, o.delta = 2, o.w = 1, o.alpha = 0.5;
  compare::HcsSummary h = compare::compute_hcs(o);
  REQUIRE(h.warnings.empty());
  h.sonine.c[1] = std::nan("");
  h.sonine.zeta_star = std::numeric_limits<double>::infinity();
  const auto w = compare::hcs_warnings(h);
  REQUIRE(w.size() == 2);
  CHECK(w[0].code == "non_finite");
  CHECK(w[0].species == 0);
  CHECK(w[0].message.find("zeta_star") != std::string::npos);
  CHECK(w[1].code == "non_finite");
  CHECK(w[1].species == 2);
  CHECK(w[1].message == "species 2: c = nan is not finite");
  // In the JSON the mixture's warning has no "species".
  const auto j = compare::hcs_warnings_json(w);
  CHECK(!j[0].contains("species"));
  CHECK(j[1]["species"].get<std::size_t>() == 2);
}
