#pragma once
// One output dimension of the DPDS (docs/models.md §4.2-§4.8): the state recursion x_t, the design
// rows r_t (x_t = r_t^T theta, theta = [mu; nu]), the weighted normal equations G theta = h, the
// gradients with respect to a (forward mode, the paper's corrected eq. 2, and adjoint), and the
// Gauss-Newton matrix of [s_t; r_t] used by variable projection + Levenberg-Marquardt. Indices are
// 0-based: frame t = 0 is the paper's t = 1.
#include <Eigen/Core>

#include <vector>

namespace lipsync::dpds {

// The label side of the problem, shared by all d dimensions.
struct LabelLayout
{
    int states = 0;                              // P
    std::vector<std::vector<int>> labels;        // per sequence
    // Per sequence: the distinct labels of frames t >= 1 in order of first visit, and for each
    // frame t >= 1 the position of its label in that list (-1 at t = 0).
    std::vector<std::vector<int>> visited;
    std::vector<std::vector<int>> local;
    Eigen::VectorXi startCount;      // N^(1)_n
    Eigen::VectorXi transitionCount; // N^{>=2}_n
    long long frames = 0;            // N
    long long transitions = 0;       // N'
};
LabelLayout makeLayout(const std::vector<std::vector<int>> &labels, int states);

// omega_1 = startWeight[pi_1], omega_t = transitionWeight (t >= 2): exact mode 1/sigma^2 and 1/r,
// paper mode all ones (§4.4).
struct Weights
{
    Eigen::VectorXd startWeight; // P
    double transitionWeight = 1.0;
};

using Series = std::vector<Eigen::VectorXd>; // one value per frame, per sequence

// x_t of every sequence (§4.1).
Series states(const LabelLayout &layout, const Eigen::VectorXd &a, const Eigen::VectorXd &theta);
// F = 1/2 sum omega_t (y_t - x_t)^2 (§4.2), without the ridge.
double weightedSquaredError(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                            const Eigen::VectorXd &theta, const Weights &w);

// Dense design rows r_t^T (rows) and sensitivities s_t^T of one sequence, for tests (§4.3, §4.7a).
Eigen::MatrixXd designRows(const LabelLayout &layout, int sequence, const Eigen::VectorXd &a);
Eigen::MatrixXd sensitivityRows(const LabelLayout &layout, int sequence, const Eigen::VectorXd &a,
                                const Eigen::VectorXd &theta);

// G = sum omega r r^T and h = sum omega r y (§4.4), split into the t = 1 part (diagonal in the
// mu block) and the unit-weight t >= 2 part, so that new weights cost O(P^2), not O(N).
struct NormalEquations
{
    Eigen::MatrixXd transitionG; // 2P x 2P, unit weights, frames t >= 2
    Eigen::VectorXd transitionH; // 2P
    Eigen::VectorXd startCount;  // P: N^(1)_n
    Eigen::VectorXd startSum;    // P: sum of y_1 over S_n
    void assemble(const Weights &w, Eigen::MatrixXd &G, Eigen::VectorXd &h) const;
};
NormalEquations normalEquations(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a);

// theta* = (G + tau I)^-1 (h + tau thetaBar) by Cholesky (§4.4 ridge).
Eigen::VectorXd solveTheta(const Eigen::MatrixXd &G, const Eigen::VectorXd &h, double tau,
                           const Eigen::VectorXd &thetaBar);

// dL/da by the forward-mode sensitivities (§4.7a) — the paper's method with eq. (2) corrected.
Eigen::VectorXd forwardGradient(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                                const Eigen::VectorXd &theta, const Weights &w);
// dL/da, dL/dmu, dL/dnu by the adjoint sweep (§4.7b). L here is -F.
void adjointGradient(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                     const Eigen::VectorXd &theta, const Weights &w, Eigen::VectorXd &gradA,
                     Eigen::VectorXd &gradMu, Eigen::VectorXd &gradNu);

// Gauss-Newton matrix H = sum omega [s; r][s; r]^T in the order [a (P); mu (P); nu (P)] and the
// gradient g = J_a^T Omega eps = dL/da (§4.8), by outer products over the visited states.
void gaussNewton(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                 const Eigen::VectorXd &theta, const Weights &w, Eigen::MatrixXd &H,
                 Eigen::VectorXd &g);

} // namespace lipsync::dpds
