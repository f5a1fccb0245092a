#include "theory/histories/msd.hpp"

#include "theory/rates/velocity_memory.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/enum_names.hpp"
#include "model/errors.hpp"
#include "model/gsl_setup.hpp"

namespace granmix::theory {

namespace {
constexpr model::EnumNames<MsdMethod, 4> msd_names = {
    {{MsdMethod::eq17, "eq17"}, {MsdMethod::vacf, "vacf"}, {MsdMethod::longtime, "longtime"}, {MsdMethod::closed, "closed"}}};
}  // namespace

MsdMethod parse_msd_method(const std::string& name) { return model::parse_enum(msd_names, name, "MSD method"); }

const char* to_string(MsdMethod m) { return model::enum_name(msd_names, m); }

namespace {

struct Eq17Integrand {
  const TemperatureHistory* h;
  std::size_t k;
  double tau_t;  // τ_k(t)
  std::unordered_map<double, Eq17Msd::Node>* kept;  // node s₁ ↦ all temperatures and τ_v⁻¹ there

  // In s₁: D_k(t₁) [1 − exp(−x)] dt₁/ds₁, x = (τ_k(t) − τ_k(t₁)) / τ̂_v,k(t₁) (v1 Eqs. 17–18).
  double operator()(double s1) {
    const double t1 = h->to_t(s1);
    const CollisionRates& r = h->rates();
    auto at = kept->find(s1);
    if (at == kept->end()) {
      Eq17Msd::Node fresh{std::vector<double>(h->species()), std::vector<double>(h->species())};
      h->temperatures(t1, fresh.T.data());
      r.inv_tau_v_all(fresh.T.data(), fresh.inv_tau.data());  // each species' sum in the order of inv_tau_v_species: the same numbers
      at = kept->emplace(s1, std::move(fresh)).first;
    }
    const std::vector<double>& T = at->second.T;
    const double inv_tau = at->second.inv_tau[k];
    const double D = T[k] / (inv_tau * r.mixture()[k].mass);                          // v1 Eq. (19)
    const double tau_hat = std::sqrt(T[k] / h->initial()[k]) / inv_tau;               // v1 Eq. (18)
    const double x = std::max(0.0, tau_t - h->reduced_time(t1, k)) / tau_hat;
    return D * -std::expm1(-x) * h->dt_ds(s1);
  }
};

}  // namespace

double Eq17Msd::operator()(std::size_t k, double t) const {
  if (t <= 0.0) return 0.0;
  if (t != t_) nodes_.clear(), t_ = t;
  model::use_gsl_return_codes();
  Eq17Integrand integrand{&h_, k, h_.reduced_time(t, k), &nodes_};
  struct Callback {
    Eq17Integrand& f;
    model::GslCallbackGuard guard;  // viscoelastic rates are quadratures that may throw
  } cb{integrand, {}};
  gsl_function f{[](double s, void* p) {
                   auto& c = *static_cast<Callback*>(p);
                   return c.guard.run(std::numeric_limits<double>::quiet_NaN(), [&] { return c.f(s); });
                 },
                 &cb};
  double result = 0.0, abserr = 0.0;
  // The integrand comes from CVODE's interpolant, which jumps by ~rtol at step boundaries: asking
  // the quadrature for less than 10 rtol is asking for noise. At the default rtol 1e-11 this is
  // 1e-9, a thousand times below the 1e-6 the MSD must reach.
  const double epsrel = std::max(1e-9, 10.0 * h_.rtol());
  const int status = gsl_integration_qag(&f, 0.0, h_.to_s(t), 0.0, epsrel, model::quadrature_intervals,
                                          GSL_INTEG_GAUSS21, model::quadrature_workspace(model::QuadratureLevel::outer), &result, &abserr);
  cb.guard.rethrow();
  if (status != GSL_SUCCESS)
    throw NumericalError(std::string("MSD Eq. (17) quadrature (gsl_integration_qag) at t = ") + std::to_string(t) +
                         ": " + gsl_strerror(status));
  return 6.0 * result;
}

double msd_eq17(const TemperatureHistory& h, std::size_t k, double t) { return Eq17Msd(h)(k, t); }

double msd_closed(double D0, double tau_v0, double tau0, double t) {
  return msd_increment(VelocityMemory::exponential(D0, tau_v0), tau0, 0.0, t);  // docs/physics.md §3 (v2 Eq. 22)
}

double msd_closed_longtime(double D0, double tau0, double t) { return 6.0 * D0 * tau0 * std::log1p(t / tau0); }

double msd_total(const model::Mixture& mix, const std::vector<double>& partial) {
  double s = 0.0;
  for (std::size_t k = 0; k < mix.size(); ++k) s += mix[k].density * partial[k];
  return s / mix.total_density();
}

}  // namespace granmix::theory
