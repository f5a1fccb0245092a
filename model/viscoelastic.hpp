#pragma once
// Viscoelastic restitution ε(y), y = (Aκ^(2/5))^(1/2) |g·e|^(1/10) (v1 Eq. 5), in three forms:
//  - exact: the contact problem x'' + x^(3/2) + b x^(1/2) x' = 0, b = y² (docs/physics.md §5),
//    solved with CVODE; a Chebyshev table built once from direct solves is what callers use;
//  - series: 1 + Σ h_j y^j with the known coefficients h_1..h_9;
//  - pade: the [3/6] Padé form of docs/physics.md §5 (1e-6 for y <= 0.5).
#include <array>
#include <string>

namespace granmix::model {

enum class ViscoelasticForm { exact, series, pade };
ViscoelasticForm parse_viscoelastic_form(const std::string& name);  // throws std::invalid_argument
const char* to_string(ViscoelasticForm f);

// h_1..h_9 of v1 Eq. (5) (docs/physics.md §5; h_1 = h_3 = 0); index 0 holds h_1.
inline constexpr std::array<double, 9> viscoelastic_h = {0.0,     -1.15344, 0.0,    0.79826, 0.26667,
                                                         -0.5229, -0.461,   0.349, 0.452};

double restitution_series(double y);
double restitution_pade(double y);
// One CVODE solve of the contact problem (slow: for tables and tests).
double restitution_contact_solve(double y);
// The tabulated exact ε(y), |error| <= 1e-9 against restitution_contact_solve for 0 <= y <= y_max.
double restitution_exact(double y);
inline constexpr double viscoelastic_table_y_max = 16.0;

double restitution(ViscoelasticForm form, double y);
// 1 − ε(y) without the cancellation of 1 − restitution(): at late times y ~ 1e-3 and 1 − ε ~ 1e-6,
// where the difference keeps only 10 digits (the collision-moment quadrature then gave up with GSL
// "roundoff error"; property tests). Series and Padé from their coefficients; exact: 1 − table.
double restitution_deficit(ViscoelasticForm form, double y);

}  // namespace granmix::model
