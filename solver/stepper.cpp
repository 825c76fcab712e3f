#include "stepper.hpp"

#include <chrono>
#include <cmath>

namespace contactbody {

namespace {

// Adds the time since the last lap to one of the timings (no cost when timing is off).
class Laps {
public:
    explicit Laps(bool on) : on_(on) { if (on_) last_ = std::chrono::steady_clock::now(); }
    void lap(double& into) {
        if (!on_) return;
        const auto now = std::chrono::steady_clock::now();
        into += std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

private:
    bool on_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace

using Cholesky = Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>;

// Factor of K = 4/dt^2 M + A on the free dofs, with its Delassus operator.
struct Stepper::Factor {
    double dt = 0;
    Cholesky cholesky;
    Eigen::MatrixXd delassus;  // (N, T) x (N, T), 2 n_c square
    SparseMatrix K_free_clamped;  // the coupling of free and clamped dofs in K
};

Stepper::Stepper(const SceneParameters& params) : params_(params), disc_(discretize(params)) {
    options_.tolerance = params.contact_tolerance;
    const Eigen::Index nf = static_cast<Eigen::Index>(disc_.free_dofs.size());
    const Eigen::Index nc = num_contact_nodes();
    z_.resize(disc_.mesh.num_dofs());
    u_half_.resize(disc_.mesh.num_dofs());
    rhs_.resize(nf);
    u_half_free_.resize(nf);
    scratch_free_.resize(nf);
    clamped_half_.resize(static_cast<Eigen::Index>(disc_.clamped_dofs.size()));
    problem_.a.resize(2 * nc);
    problem_.gap_limit.resize(nc);
    problem_.slip_origin.resize(nc);
}

Stepper::~Stepper() = default;

State Stepper::initial_state(double top_displacement) const {
    State s;
    const Mesh& mesh = disc_.mesh;
    s.u.setZero(mesh.num_dofs());
    s.v.setZero(mesh.num_dofs());
    for (int n = 0; n < mesh.num_nodes(); ++n)
        s.u[dof_y(n)] = top_displacement * mesh.point(n).y / mesh.height;
    s.lambda.setZero(params_.friction_coefficient > 0 ? 2 * num_contact_nodes()
                                                      : num_contact_nodes());
    return s;
}

void Stepper::set_friction_coefficient(double friction) {
    params_.friction_coefficient = friction;
    problem_factor_ = nullptr;  // the problem's size may change: rebuild W on next use
}

Stepper::Factor& Stepper::factor_for(double dt) {
    for (int k = 0; k < 2; ++k) {
        if (cache_[k] && std::abs(cache_[k]->dt - dt) <= 1e-14 * dt) {
            if (k == 1) std::swap(cache_[0], cache_[1]);
            return *cache_[0];
        }
    }
    auto f = std::make_unique<Factor>();
    f->dt = dt;
    const SparseMatrix K = (4.0 / (dt * dt)) * disc_.M_free + disc_.A_free;
    f->cholesky.compute(K);
    f->K_free_clamped = (4.0 / (dt * dt)) * disc_.M_free_clamped + disc_.A_free_clamped;
    if (f->cholesky.info() != Eigen::Success)
        throw std::runtime_error("Cholesky factorization of 4/dt^2 M + A failed");
    ++factorizations_;

    // W = B K^-1 B^T, one block of right-hand sides at a time to bound memory.
    const int nc = num_contact_nodes(), m = 2 * nc;
    const Eigen::Index nf = static_cast<Eigen::Index>(disc_.free_dofs.size());
    f->delassus.resize(m, m);
    constexpr int block = 32;
    Eigen::MatrixXd rhs(nf, block);
    for (int c0 = 0; c0 < m; c0 += block) {
        const int width = std::min(block, m - c0);
        rhs.setZero();
        for (int j = 0; j < width; ++j) {
            const int c = c0 + j;  // B rows: N_i = -e_y(i), T_i = +e_x(i)
            if (c < nc) rhs(disc_.contact_y[c], j) = -1;
            else rhs(disc_.contact_x[c - nc], j) = 1;
        }
        const Eigen::MatrixXd x = f->cholesky.solve(rhs.leftCols(width));
        for (int i = 0; i < nc; ++i) {
            f->delassus.block(i, c0, 1, width) = -x.row(disc_.contact_y[i]);
            f->delassus.block(nc + i, c0, 1, width) = x.row(disc_.contact_x[i]);
        }
    }
    cache_[1] = std::move(cache_[0]);
    cache_[0] = std::move(f);
    return *cache_[0];
}

void Stepper::setup_contact_problem(const Factor& f) {
    const int nc = num_contact_nodes();
    const bool friction = params_.friction_coefficient > 0;
    problem_.W = friction ? f.delassus : Eigen::MatrixXd(f.delassus.topLeftCorner(nc, nc));
    problem_.a.resize(friction ? 2 * nc : nc);
    problem_.friction = params_.friction_coefficient;
    snapshot_.delassus_diagonal = f.delassus.diagonal();
    problem_factor_ = &f;
}

SubstepReport Stepper::substep(State& s, double dt, const SubstepLoad& load) {
    Laps laps(timing_);
    const Factor& f = factor_for(dt);
    if (problem_factor_ != &f) setup_contact_problem(f);
    laps.lap(timings_.factor);
    const Discretization& d = disc_;
    const int nc = num_contact_nodes();
    const bool friction = problem_.has_friction();
    const double c1 = 4.0 / (dt * dt), c2 = 2.0 / dt;
    if (s.lambda.size() != problem_.W.rows()) s.lambda.setZero(problem_.W.rows());

    // Clamped dofs at the midpoint: u_x = 0, u_y = mean top displacement.
    const double top_half = 0.5 * (load.top_start + load.top_end);
    for (Eigen::Index k = 0; k < clamped_half_.size(); ++k)
        clamped_half_[k] = d.clamped_dofs[k] % 2 == 1 ? top_half : 0.0;

    z_ = c1 * s.u + c2 * s.v;
    rhs_.noalias() = d.M_free_rows * z_;
    rhs_.noalias() -= f.K_free_clamped * clamped_half_;
    laps.lap(timings_.update);
    u_half_free_ = f.cholesky.solve(rhs_);
    laps.lap(timings_.solve);

    // Condensed contact problem on u^{k+1/2}; the standard_implicit_contact variant
    // imposes the conditions at the end of the step, an affine map of u^{k+1/2}.
    const bool implicit = params_.mass_matrix == MassVariant::standard_implicit_contact;
    bool touching = false;
    for (int i = 0; i < nc; ++i) {
        const int node = d.mesh.contact_nodes[i];
        const double uN_old = -s.u[dof_y(node)];
        problem_.a[i] = -u_half_free_[d.contact_y[i]];
        problem_.gap_limit[i] = implicit ? 0.5 * (params_.initial_gap + uN_old)
                                         : params_.initial_gap;
        touching = touching || problem_.a[i] > problem_.gap_limit[i];
        if (friction) {
            problem_.a[nc + i] = u_half_free_[d.contact_x[i]];
            const double ux_old = s.u[dof_x(node)], vx_old = s.v[dof_x(node)];
            problem_.slip_origin[i] =
                implicit ? ux_old + 0.25 * dt * (vx_old + load.foundation_velocity)
                         : ux_old + 0.5 * dt * load.foundation_velocity;
        }
    }
    SubstepReport report;
    if (touching) {
        report.contact_iterations = solver_.solve(problem_, options_, s.lambda).iterations;
        report.contact_solved = true;
        for (int i = 0; i < nc; ++i) {
            rhs_[d.contact_y[i]] -= s.lambda[i];
            if (friction) rhs_[d.contact_x[i]] += s.lambda[nc + i];
        }
        laps.lap(timings_.contact);
        u_half_free_ = f.cholesky.solve(rhs_);
        laps.lap(timings_.solve);
    } else {
        s.lambda.setZero();  // no node can touch: the contact solve is skipped
        laps.lap(timings_.contact);
    }

    for (size_t k = 0; k < d.free_dofs.size(); ++k) u_half_[d.free_dofs[k]] = u_half_free_[k];
    for (size_t k = 0; k < d.clamped_dofs.size(); ++k) u_half_[d.clamped_dofs[k]] = clamped_half_[k];

    // Force of the clamp on the body: the clamped rows' residual of the midpoint equation.
    for (Eigen::Index k = 0; k < clamped_half_.size(); ++k) {
        double r = 0;
        for (RowMajorSparseMatrix::InnerIterator it(d.M_clamped_rows, k); it; ++it)
            r += it.value() * (c1 * u_half_[it.col()] - z_[it.col()]);
        for (RowMajorSparseMatrix::InnerIterator it(d.A_clamped_rows, k); it; ++it)
            r += it.value() * u_half_[it.col()];
        (d.clamped_dofs[k] % 2 == 0 ? report.top_reaction_x : report.top_reaction_y) += r;
    }

    snapshot_.normal_displacement.resize(nc);
    snapshot_.gap_limit = problem_.gap_limit;
    snapshot_.slip.setZero(nc);
    snapshot_.lambda_N = s.lambda.head(nc);
    snapshot_.lambda_T.resize(nc);  // no reallocation once sized
    if (friction) snapshot_.lambda_T = s.lambda.tail(nc);
    else snapshot_.lambda_T.setZero();
    for (int i = 0; i < nc; ++i) {
        const int node = d.mesh.contact_nodes[i];
        snapshot_.normal_displacement[i] = -u_half_[dof_y(node)];
        if (friction) snapshot_.slip[i] = u_half_[dof_x(node)] - problem_.slip_origin[i];
        const double lN = snapshot_.lambda_N[i], lT = snapshot_.lambda_T[i];
        const double ux_new = 2 * u_half_[dof_x(node)] - s.u[dof_x(node)];
        const double uN_new = -(2 * u_half_[dof_y(node)] - s.u[dof_y(node)]);
        report.normal_force -= lN;
        report.friction_force += lT;
        report.friction_work += lT * (ux_new - s.u[dof_x(node)]);
        report.max_penetration =
            std::max(report.max_penetration, uN_new - params_.initial_gap);
        if (touching && solver_.status()[i] != NodeStatus::open) {
            ++report.active_nodes;
            if (solver_.status()[i] == NodeStatus::slip) ++report.slipping_nodes;
        }
    }
    report.corner_lambda_N = snapshot_.lambda_N[0];
    report.corner_lambda_T = snapshot_.lambda_T[0];

    // u^{k+1} = 2 u^{k+1/2} - u^k,  v^{k+1} = 4/dt (u^{k+1/2} - u^k) - v^k on the free dofs;
    // the clamped dofs follow the top displacement input.
    for (int dof : d.free_dofs) {
        const double du = u_half_[dof] - s.u[dof];
        s.v[dof] = 2 * c2 * du - s.v[dof];
        s.u[dof] += 2 * du;
    }
    for (int dof : d.clamped_dofs) {
        const bool y = dof % 2 == 1;
        s.u[dof] = y ? load.top_end : 0.0;
        s.v[dof] = y ? load.top_rate : 0.0;
    }
    s.time += dt;
    laps.lap(timings_.update);
    return report;
}

}  // namespace contactbody
