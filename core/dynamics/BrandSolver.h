#pragma once
// The linear algebra of Brand / MLPG generation (docs/models.md §2.2): the maximiser of the static
// + delta objective solves H y = b with H = W^T Lambda W.
//  - diagonal covariances: d independent symmetric tridiagonal systems, LDL^T (Thomas), O(dT);
//  - full covariances: one block-tridiagonal system with d x d blocks, block LDL^T, O(d^3 T);
//  - a dense reference (explicit W, Lambda) for tests and benchmarks, small T only.
#include <Eigen/Core>

#include <vector>

namespace lipsync::brand {

// Per-frame coefficients of one dimension k (t = 0..T-1 here, §2.2 uses 1..T):
// p_t = 1/c^y, mbar_t = m^y, q_t = 1/c^Delta and deltabar_t = m^Delta of frame t's label, with
// q_0 = deltabar_0 = 0 (frame 1 has no delta term).
struct TridiagonalSystem
{
    Eigen::VectorXd alpha; // H_tt, T
    Eigen::VectorXd beta;  // H_t,t+1, T-1
    Eigen::VectorXd b;     // T
};

TridiagonalSystem buildTridiagonal(const Eigen::VectorXd &p, const Eigen::VectorXd &mbar,
                                   const Eigen::VectorXd &q, const Eigen::VectorXd &deltabar);

// LDL^T solve without pivoting (H is SPD and diagonally dominant). Optionally returns the pivots
// d_t (log|H| = sum log d_t) and multipliers l_t (l_0 = 0).
Eigen::VectorXd solveTridiagonal(const TridiagonalSystem &system, Eigen::VectorXd *pivots = nullptr,
                                 Eigen::VectorXd *multipliers = nullptr);

// Symmetric block-tridiagonal H: diagonal blocks H_tt (T) and sub-diagonal blocks H_{t+1,t}
// (T-1); H_{t,t+1} = H_{t+1,t}^T. rhs is d x T.
struct BlockTridiagonalSystem
{
    std::vector<Eigen::MatrixXd> diagonal;
    std::vector<Eigen::MatrixXd> lower;
    Eigen::MatrixXd rhs;
};

// What frame t, in state n, adds to the system (§2.2): to its own diagonal block and right-hand
// side, to frame t-1's diagonal block and right-hand side, and the sub-diagonal block H_{t,t-1}
// (zero for the first frame, which has no delta term).
struct BlockTerms
{
    Eigen::MatrixXd diagonal, previousDiagonal, lower;
    Eigen::VectorXd rhs, previousRhs;
};

// Block LDL^T with a Cholesky factor of every pivot block (§2.2). Returns d x T.
// Throws lipsync::Error if a pivot block is not positive definite.
Eigen::MatrixXd solveBlockTridiagonal(const BlockTridiagonalSystem &system);

// Dense dT x dT assembly of a block-tridiagonal system (unknowns ordered y_1, y_2, ...).
Eigen::MatrixXd denseMatrix(const BlockTridiagonalSystem &system);
Eigen::VectorXd denseRhs(const BlockTridiagonalSystem &system);
// Dense Cholesky solve of the assembled system: the O((dT)^3) reference.
Eigen::MatrixXd solveDense(const BlockTridiagonalSystem &system);

} // namespace lipsync::brand
