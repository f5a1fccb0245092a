#include "viscoelastic.hpp"

#include <gsl/gsl_chebyshev.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cvode_session.hpp"
#include "enum_names.hpp"
#include "errors.hpp"
#include "gsl_setup.hpp"
#include "sundials_check.hpp"

namespace granmix::model {

namespace {
constexpr EnumNames<ViscoelasticForm, 3> form_names = {
    {{ViscoelasticForm::exact, "exact"}, {ViscoelasticForm::series, "series"}, {ViscoelasticForm::pade, "pade"}}};
}  // namespace

ViscoelasticForm parse_viscoelastic_form(const std::string& name) { return parse_enum(form_names, name, "viscoelastic form"); }

const char* to_string(ViscoelasticForm f) { return enum_name(form_names, f); }

namespace {

// Σ h_j y^j of v1 Eq. (5), Horner in y.
double series_sum(double y) {
  double s = 0.0;
  for (std::size_t j = viscoelastic_h.size(); j-- > 0;) s = (s + viscoelastic_h[j]) * y;
  return s;
}

}  // namespace

double restitution_series(double y) { return 1.0 + series_sum(y); }

double restitution_pade(double y) {
  // docs/physics.md §5, [3/6] Padé in y.
  const double num = 1 + y * (1.07232 + y * (0.574198 + y * 0.141552));
  const double den =
      1 + y * (1.07232 + y * (1.72765 + y * (1.37842 + y * (1.19449 + y * (0.467273 + y * 0.235585)))));
  return num / den;
}

namespace {

// x'' = -x^(3/2) - b x^(1/2) x'  (dimensionless contact problem, docs/physics.md §5)
int contact_rhs(sunrealtype, N_Vector u, N_Vector du, void* data) {
  const double b = *static_cast<double*>(data);
  const double x = NV_Ith_S(u, 0), v = NV_Ith_S(u, 1);
  const double sx = std::sqrt(x > 0 ? x : 0.0);
  NV_Ith_S(du, 0) = v;
  NV_Ith_S(du, 1) = -sx * (x + b * v);
  return 0;
}

// Contact ends when the force x^(1/2)(x + b x') vanishes, i.e. x + b x' = 0 (not when x = 0).
int contact_end(sunrealtype, N_Vector u, sunrealtype* g, void* data) {
  const double b = *static_cast<double*>(data);
  g[0] = NV_Ith_S(u, 0) + b * NV_Ith_S(u, 1);
  return 0;
}

}  // namespace

double restitution_contact_solve(double y) {
  if (!(y >= 0.0) || !std::isfinite(y)) throw std::invalid_argument("restitution: y must be >= 0");
  if (y == 0.0) return 1.0;  // elastic: Hertz contact without dissipation
  double b = y * y;
  CvodeSession cv(2, contact_rhs, &b);
  cv.data()[0] = 0.0;  // x(0) = 0, x'(0) = 1: velocities in units of the impact speed
  cv.data()[1] = 1.0;
  // 1e-13: the table must match direct solves to 1e-9 and the published values to 1e-6.
  const double atol[2] = {1e-15, 1e-15};
  cv.init(0.0, 1e-13, atol);
  check_cvode(CVodeSetMaxNumSteps(cv.mem(), 200000), "CVodeSetMaxNumSteps");
  check_cvode(CVodeRootInit(cv.mem(), 1, contact_end), "CVodeRootInit");
  // The contact lasts a time of order one (Hertz) or shorter (strong damping); integrate in
  // chunks until the root is found.
  double t = 0.0;
  for (double tout = 1.0; tout < 1e6; tout *= 2.0) {
    const int flag = CVode(cv.mem(), tout, cv.y(), &t, CV_NORMAL);
    check_cvode(flag, "CVode", "viscoelastic contact problem, y = " + std::to_string(y));
    if (flag == CV_ROOT_RETURN) return -cv.data()[1];
  }
  throw NumericalError("viscoelastic contact problem: contact did not end (y = " + std::to_string(y) + ")");
}

namespace {

// Piecewise Chebyshev fit of the exact ε(y): narrow pieces where ε falls fastest (y < 2), wide
// ones above, where ε is small and smooth. With order 18 the worst piece is below 1e-10
// (tests check 1e-9 against direct solves); building it costs about 230 contact solves.
class ExactTable {
 public:
  ExactTable() {
    use_gsl_return_codes();
    static constexpr double edges[] = {0, 0.25, 0.5, 0.75, 1, 1.5, 2, 3, 4, 6, 8, 12, viscoelastic_table_y_max};
    for (std::size_t p = 0; p + 1 < std::size(edges); ++p) {
      gsl_cheb_series* cs = gsl_cheb_alloc(order_);
      if (cs == nullptr) throw NumericalError("gsl_cheb_alloc failed");
      series_.push_back(cs);
      gsl_function f{[](double y, void*) { return restitution_contact_solve(y); }, nullptr};
      if (gsl_cheb_init(cs, &f, edges[p], edges[p + 1]) != 0)
        throw NumericalError("gsl_cheb_init failed for the viscoelastic table");
      upper_.push_back(edges[p + 1]);
    }
  }
  ~ExactTable() {
    for (gsl_cheb_series* cs : series_) gsl_cheb_free(cs);
  }
  ExactTable(const ExactTable&) = delete;
  ExactTable& operator=(const ExactTable&) = delete;

  double operator()(double y) const {
    if (!(y >= 0.0) || y > viscoelastic_table_y_max)
      throw std::domain_error("viscoelastic restitution: y = " + std::to_string(y) +
                              " outside the exact table [0, " + std::to_string(viscoelastic_table_y_max) +
                              "]: impact speed too high for the tabulated contact problem");
    std::size_t p = 0;
    while (y > upper_[p]) ++p;  // a dozen pieces: a linear scan beats a bisection here
    return gsl_cheb_eval(series_[p], y);
  }

 private:
  static constexpr std::size_t order_ = 18;
  std::vector<gsl_cheb_series*> series_;
  std::vector<double> upper_;
};

}  // namespace

double restitution_exact(double y) {
  static const ExactTable table;  // built once, thread-safe initialisation
  return table(y);
}

double restitution(ViscoelasticForm form, double y) {
  switch (form) {
    case ViscoelasticForm::exact: return restitution_exact(y);
    case ViscoelasticForm::series: return restitution_series(y);
    case ViscoelasticForm::pade: return restitution_pade(y);
  }
  throw std::logic_error("unknown viscoelastic form");
}

double restitution_deficit(ViscoelasticForm form, double y) {
  switch (form) {
    case ViscoelasticForm::exact: return 1.0 - restitution_exact(y);
    case ViscoelasticForm::series: return -series_sum(y);
    case ViscoelasticForm::pade: {
      // den − num of restitution_pade: the constant and linear terms cancel exactly.
      const double diff =
          y * y * ((1.72765 - 0.574198) + y * ((1.37842 - 0.141552) + y * (1.19449 + y * (0.467273 + y * 0.235585))));
      const double den =
          1 + y * (1.07232 + y * (1.72765 + y * (1.37842 + y * (1.19449 + y * (0.467273 + y * 0.235585)))));
      return diff / den;
    }
  }
  throw std::logic_error("unknown viscoelastic form");
}

}  // namespace granmix::model
