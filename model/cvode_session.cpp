#include "cvode_session.hpp"

#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "sundials_check.hpp"

namespace granmix::model {

CvodeSession::CvodeSession(std::size_t n, CVRhsFn rhs, void* user_data, LinearSolver solver)
    : n_(n), rhs_(rhs), user_data_(user_data), solver_(solver) {
  check_cvode(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
  y_ = check_alloc(N_VNew_Serial(static_cast<sunindextype>(n_), ctx_), "N_VNew_Serial");
  atol_ = check_alloc(N_VNew_Serial(static_cast<sunindextype>(n_), ctx_), "N_VNew_Serial");
  N_VConst(0.0, y_);
}

CvodeSession::~CvodeSession() {
  if (mem_) CVodeFree(&mem_);
  if (LS_) SUNLinSolFree(LS_);
  if (A_) SUNMatDestroy(A_);
  if (atol_) N_VDestroy(atol_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
}

void CvodeSession::init(double t0, double rtol, const double* atol) {
  double* a = N_VGetArrayPointer(atol_);
  for (std::size_t i = 0; i < n_; ++i) a[i] = atol[i];
  mem_ = check_alloc(CVodeCreate(CV_BDF, ctx_), "CVodeCreate");
  check_cvode(CVodeInit(mem_, rhs_, t0, y_), "CVodeInit");
  check_cvode(CVodeSVtolerances(mem_, rtol, atol_), "CVodeSVtolerances");
  check_cvode(CVodeSetUserData(mem_, user_data_), "CVodeSetUserData");
  if (solver_ == LinearSolver::gmres) {
    LS_ = check_alloc(SUNLinSol_SPGMR(y_, SUN_PREC_NONE, 0, ctx_), "SUNLinSol_SPGMR");
    check_cvode(CVodeSetLinearSolver(mem_, LS_, nullptr), "CVodeSetLinearSolver");
  } else {
    const auto n = static_cast<sunindextype>(n_);
    A_ = check_alloc(SUNDenseMatrix(n, n, ctx_), "SUNDenseMatrix");
    LS_ = check_alloc(SUNLinSol_Dense(y_, A_, ctx_), "SUNLinSol_Dense");
    check_cvode(CVodeSetLinearSolver(mem_, LS_, A_), "CVodeSetLinearSolver");
  }
}

}  // namespace granmix::model
