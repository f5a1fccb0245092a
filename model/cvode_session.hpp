#pragma once
// One CVODE integrator with everything it owns (context, state vector, matrix, linear solver),
// freed together. Both the viscoelastic contact problem and the temperature ODEs use it.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cstddef>

namespace granmix::model {

enum class LinearSolver { dense, gmres };

class CvodeSession {
 public:
  // BDF, dense Newton (few unknowns) or GMRES without preconditioner (hundreds of unknowns,
  // the Jacobian is never formed).
  CvodeSession(std::size_t n, CVRhsFn rhs, void* user_data, LinearSolver solver = LinearSolver::dense);
  ~CvodeSession();
  CvodeSession(const CvodeSession&) = delete;
  CvodeSession& operator=(const CvodeSession&) = delete;

  // Set the initial state (y) at t0 and initialise CVODE with scalar relative and
  // per-component absolute tolerances.
  void init(double t0, double rtol, const double* atol);

  void* mem() const { return mem_; }
  N_Vector y() const { return y_; }
  double* data() const { return N_VGetArrayPointer(y_); }
  SUNContext context() const { return ctx_; }

 private:
  std::size_t n_;
  CVRhsFn rhs_;
  void* user_data_;
  LinearSolver solver_;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  N_Vector atol_ = nullptr;
  SUNMatrix A_ = nullptr;
  SUNLinearSolver LS_ = nullptr;
  void* mem_ = nullptr;
};

}  // namespace granmix::model
