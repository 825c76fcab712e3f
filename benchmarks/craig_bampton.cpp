#include "craig_bampton.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "reduced/modal_basis.hpp"

namespace contactbody {

CraigBamptonStepper::CraigBamptonStepper(const SceneParameters& params, int modes)
    : params_(params), disc_(discretize(params)), modes_(modes) {
    const auto start = std::chrono::steady_clock::now();
    const Discretization& d = disc_;
    if (d.plate_index >= 0)
        throw std::invalid_argument("Craig-Bampton reduction needs top_control = displacement");
    const Eigen::Index nf = d.A_free.rows();
    const int nc = num_contact_nodes();
    // The edge coordinates in the contact unknowns' order (y then x), the interior the rest.
    const std::vector<int> edge = d.contact_unknowns();
    std::vector<bool> on_edge(static_cast<size_t>(nf), false);
    for (int p : edge) on_edge[static_cast<size_t>(p)] = true;
    std::vector<int> interior;
    for (int p = 0; p < nf; ++p)
        if (!on_edge[static_cast<size_t>(p)]) interior.push_back(p);
    const SparseMatrix Pi = selection(nf, interior), Pb = selection(nf, edge);
    const SparseMatrix Aii = Pi.transpose() * d.A_free * Pi, Mii = Pi.transpose() * d.M_free * Pi;
    const SparseMatrix Aib = Pi.transpose() * d.A_free * Pb;
    const Eigen::Index ni = static_cast<Eigen::Index>(interior.size());
    if (modes < 1 || modes > ni)
        throw std::invalid_argument("Craig-Bampton: modes = " + std::to_string(modes) +
                                    " is out of range: the interior has " + std::to_string(ni) + " dofs");
    const LowestModes fixed = lowest_modes(Aii, Mii, modes);
    highest_hz_ = std::sqrt(fixed.omega2.maxCoeff()) / (2 * M_PI);
    const Eigen::MatrixXd constraint = -fixed.solve(Eigen::MatrixXd(Aib));  // ni x 2 n_c

    const Eigen::Index nb = 2 * nc, n = modes + nb;
    Eigen::MatrixXd interior_columns(ni, n);
    interior_columns << fixed.modes, constraint;
    T_ = Pi * interior_columns;
    for (Eigen::Index j = 0; j < nb; ++j) T_(edge[static_cast<size_t>(j)], modes + j) = 1.0;

    const Eigen::Index ncl = static_cast<Eigen::Index>(d.clamped_dofs.size());
    Eigen::VectorXd e = Eigen::VectorXd::Zero(ncl);
    for (Eigen::Index j = 0; j < ncl; ++j)
        e[j] = d.mesh.component(d.clamped_dofs[static_cast<size_t>(j)]) == Mesh::normal;
    const Eigen::VectorXd Afc_e = d.A_free_clamped * e, Mfc_e = d.M_free_clamped * e;
    lift_ = Pi * Eigen::VectorXd(-fixed.solve(Eigen::MatrixXd(Pi.transpose() * Afc_e)).col(0));

    const Eigen::MatrixXd MT = d.M_free * T_, AT = d.A_free * T_;
    mass_ = T_.transpose() * MT;
    stiffness_ = T_.transpose() * AT;
    mass_ = 0.5 * (mass_ + mass_.transpose()).eval();
    stiffness_ = 0.5 * (stiffness_ + stiffness_.transpose()).eval();
    stiffness_factor_.compute(stiffness_);
    const Eigen::VectorXd& S = lift_;
    const Eigen::VectorXd MS = d.M_free * S, AS = d.A_free * S;
    m_s_ = T_.transpose() * MS;
    m_c_ = T_.transpose() * Mfc_e;
    a_s_ = T_.transpose() * AS;
    a_c_ = T_.transpose() * Afc_e;
    m_t_ = m_s_ + m_c_;
    a_t_ = a_s_ + a_c_;
    Eigen::VectorXd all_e = Eigen::VectorXd::Zero(d.mesh.num_dofs());
    for (Eigen::Index j = 0; j < ncl; ++j) all_e[d.clamped_dofs[static_cast<size_t>(j)]] = e[j];
    mu_ss_ = S.dot(MS);
    mu_cs_ = S.dot(Mfc_e);
    mu_cc_ = all_e.dot(d.M * all_e);
    s_ss_ = S.dot(AS);
    s_cs_ = S.dot(Afc_e);
    e_cc_ = all_e.dot(d.A * all_e);

    Bhat_.resize(nb, n);
    Blift_.resize(nb);
    for (int i = 0; i < nc; ++i) {  // N_i = -e_y(i), T_i = +e_x(i)
        const int y = d.contact_y[static_cast<size_t>(i)],
                  x = d.contact_tangential[0][static_cast<size_t>(i)];
        Bhat_.row(i) = -T_.row(y);
        Bhat_.row(nc + i) = T_.row(x);
        Blift_[i] = -S[y];
        Blift_[nc + i] = S[x];
    }
    const ClampXRows x_rows = clamp_x_rows(d);
    clamp_x_.mass = T_.transpose() * x_rows.mass_free;
    clamp_x_.stiffness = T_.transpose() * x_rows.stiffness_free;
    clamp_x_.mass_lift = S.dot(x_rows.mass_free);
    clamp_x_.stiffness_lift = S.dot(x_rows.stiffness_free);
    clamp_x_.mass_top = x_rows.mass_top;
    clamp_x_.stiffness_top = x_rows.stiffness_top;

    problem_.a.resize(nb);
    problem_.gap_limit.resize(nc);
    problem_.slip_origin.resize(nc);
    start_run();
    setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void CraigBamptonStepper::start_run() {
    damping_ = params_.damping_mass * mass_ + params_.damping_stiffness * stiffness_;
    damping_coupling_ = params_.damping_mass * m_t_ + params_.damping_stiffness * a_t_;
    options_ = ContactSolverOptions{};
    options_.tolerance = params_.contact_tolerance;
    solver_ = ContactSolver{};
    snapshot_ = ContactSnapshot{};
    problem_dt_ = -1;
}

void CraigBamptonStepper::restart(const SceneParameters& params) {
    if (!same_discretization(params_, params))
        throw std::logic_error("CraigBamptonStepper::restart: another discretization");
    check_parameters(params);
    params_ = params;
    start_run();
}

State CraigBamptonStepper::from_full(const State& full) const {
    const Discretization& d = disc_;
    const Eigen::Index n = size();
    State s;
    Eigen::VectorXd u, v;  // the free dofs' motion less the lift's
    split_off_lift(d, d.clamped_dofs.back(), lift_, full, n, s, u, v);
    s.u.head(n) = stiffness_factor_.solve(T_.transpose() * (d.A_free * u));
    s.v.head(n) = stiffness_factor_.solve(T_.transpose() * (d.A_free * v));
    return s;
}

void CraigBamptonStepper::to_full(const State& s, State& full) const {
    const Discretization& d = disc_;
    const Eigen::Index n = size();
    const Eigen::VectorXd u = T_ * s.u.head(n) + lift_ * s.u[n];
    const Eigen::VectorXd v = T_ * s.v.head(n) + lift_ * s.v[n];
    expand_to_full(d, u, v, s, n, full);
}

State CraigBamptonStepper::initial_state(double top_displacement) const {
    return from_full(Stepper::paper_initial_state(disc_, params_, top_displacement));
}

std::pair<double, double> CraigBamptonStepper::kinetic_and_strain_energy(const State& s) {
    const Eigen::Index n = size();
    const auto y = s.u.head(n), ydot = s.v.head(n);
    const double tau = s.v[n], tc = s.v[n + 1], lift = s.u[n], top = s.u[n + 1];
    const double kinetic = 0.5 * ydot.dot(mass_ * ydot) + ydot.dot(m_s_ * tau + m_c_ * tc) +
                           0.5 * (mu_ss_ * tau * tau + 2 * mu_cs_ * tau * tc + mu_cc_ * tc * tc);
    const double strain = 0.5 * y.dot(stiffness_ * y) + y.dot(a_s_ * lift + a_c_ * top) +
                          0.5 * (s_ss_ * lift * lift + 2 * s_cs_ * lift * top + e_cc_ * top * top);
    return {kinetic, strain};
}

double CraigBamptonStepper::contact_height(const State& s, int node) const {
    return -(Bhat_.row(node).dot(s.u.head(size())) + Blift_[node] * s.u[size()]);
}

bool CraigBamptonStepper::set_clamp(State& s, double top, double rate) const {
    const Eigen::Index n = size();
    const bool moves = s.u[n + 1] != top || s.v[n + 1] != rate;
    s.u[n + 1] = top;
    s.v[n + 1] = rate;
    return moves;
}

bool CraigBamptonStepper::fits(const State& s) const {
    const Eigen::Index nc = num_contact_nodes();
    return s.u.size() == size() + 2 && s.v.size() == size() + 2 &&
           (s.lambda.size() == nc || s.lambda.size() == 2 * nc) && s.sticking.size() == nc;
}

std::vector<double> CraigBamptonStepper::cached_substeps() const {
    std::vector<double> sizes;
    for (const auto& ops : cache_)
        if (ops) sizes.push_back(ops->dt);
    return sizes;
}

void CraigBamptonStepper::set_cached_substeps(const std::vector<double>& sizes) {
    if (sizes.size() > cache_.size())
        throw std::invalid_argument("more cached substep sizes than the cache holds");
    for (auto& ops : cache_) ops.reset();
    for (size_t k = sizes.size(); k-- > 0;) build_operators(sizes[k]);
    problem_dt_ = -1;
}

void CraigBamptonStepper::set_friction_coefficient(double friction) {
    params_.friction_coefficient = friction;
    problem_dt_ = -1;
}

const CraigBamptonStepper::StepOperators& CraigBamptonStepper::operators_for(double dt) {
    for (const auto& ops : cache_)
        if (ops && std::abs(ops->dt - dt) <= 1e-14 * dt) return *ops;
    return build_operators(dt);
}

CraigBamptonStepper::StepOperators& CraigBamptonStepper::build_operators(double dt) {
    std::swap(cache_[0], cache_[1]);
    auto ops = std::make_unique<StepOperators>();
    ops->dt = dt;
    ops->stiffness.compute((4.0 / (dt * dt)) * mass_ + (2.0 / dt) * damping_ + stiffness_);
    if (ops->stiffness.info() != Eigen::Success)
        throw std::runtime_error("Craig-Bampton step matrix is not positive definite");
    ops->delassus = Bhat_ * ops->stiffness.solve(Eigen::MatrixXd(Bhat_.transpose()));
    ops->delassus = 0.5 * (ops->delassus + ops->delassus.transpose()).eval();
    cache_[0] = std::move(ops);
    ++operator_builds_;
    return *cache_[0];
}

// The reduced body's substep (reduced_stepper.cpp) with dense M_hat, A_hat, C_hat and the
// lift coupled to both (a_s + a_c need not vanish: the lift holds the edge).
SubstepReport CraigBamptonStepper::substep(State& s, double dt, const SubstepLoad& load) {
    const StepOperators& ops = operators_for(dt);
    const int nc = num_contact_nodes();
    const bool friction = params_.friction_coefficient > 0;
    if (problem_dt_ != dt || problem_friction_ != friction) {
        problem_.set_operator(ops.delassus, params_.friction_coefficient);
        problem_dt_ = dt;
        problem_friction_ = friction;
    }
    const double c1 = 4.0 / (dt * dt), c2 = 2.0 / dt;
    const double alpha = params_.damping_mass, beta = params_.damping_stiffness;
    if (s.lambda.size() != problem_.W.rows()) s.lambda.setZero(problem_.W.rows());
    const Eigen::Index n = size();
    auto y = s.u.head(n), ydot = s.v.head(n);
    double& lift_at = s.u[n];
    double& lift_rate = s.v[n];
    double& top = s.u[n + 1];
    double& top_rate = s.v[n + 1];

    const double w_t = 0.5 * (load.top_start + load.top_end) - top;
    rhs_ = c2 * (mass_ * ydot + m_s_ * lift_rate + m_c_ * top_rate) - stiffness_ * y - a_s_ * lift_at -
           a_c_ * top - ((c1 + c2 * alpha) * w_t) * m_t_ - ((1 + c2 * beta) * w_t) * a_t_;
    w_ = ops.stiffness.solve(rhs_);
    contact_u_ = Bhat_ * y + Blift_ * lift_at;
    bw_ = Bhat_ * w_ + Blift_ * w_t;
    problem_.a = bw_.head(problem_.a.size());
    const bool touching = set_contact_conditions(
        problem_, params_, disc_.contact_at_end_of_step, dt, load, s.sticking,
        [&](int i) { return params_.initial_gap + disc_.mesh.contact_heights[i] - contact_u_[i]; });
    SubstepReport report;
    const Eigen::Index unknowns = problem_.W.rows();
    if (touching) {
        const ContactSolveInfo info = solver_.solve(problem_, options_, s.lambda);
        report.contact_iterations = info.iterations;
        report.contact_sweeps = info.sweeps;
        report.contact_solved = true;
        w_ += ops.stiffness.solve(Eigen::VectorXd(Bhat_.topRows(unknowns).transpose() * s.lambda));
        bw_ = Bhat_ * w_ + Blift_ * w_t;
    } else {
        s.lambda.setZero();
    }

    const double du_t = 2 * w_t;
    du_ = 2 * w_;
    const double mass_tt = mu_ss_ + 2 * mu_cs_ + mu_cc_, stiffness_tt = s_ss_ + 2 * s_cs_ + e_cc_;
    const Eigen::VectorXd& coupling_c = damping_coupling_;
    if (params_.damped())
        report.work.damping = (du_.dot(damping_ * du_) + 2 * du_t * coupling_c.dot(du_) +
                               (alpha * mass_tt + beta * stiffness_tt) * du_t * du_t) /
                              dt;
    // The clamp's force: the residual of the lift's and the clamp's rows, less the contact
    // forces' share through the lift.
    double r = m_t_.dot(c1 * w_ - c2 * ydot) + (mu_ss_ + mu_cs_) * (c1 * w_t - c2 * lift_rate) +
               (mu_cs_ + mu_cc_) * (c1 * w_t - c2 * top_rate) + a_t_.dot(y + w_) +
               (s_ss_ + s_cs_) * (lift_at + w_t) + (s_cs_ + e_cc_) * (top + w_t);
    if (params_.damped())
        r += 0.5 * c2 * (coupling_c.dot(du_) + (alpha * mass_tt + beta * stiffness_tt) * du_t);
    r -= Blift_.head(unknowns).dot(s.lambda);
    report.top_reaction[1] = r;
    report.work.clamp = r * du_t;
    report.top_reaction[0] = clamp_x_.residual(
        {c1, c2, w_t, lift_at, lift_rate, top, top_rate, alpha, beta, params_.damped()}, y, ydot, w_, du_);

    record_contact(
        report, snapshot_, s.sticking, s.lambda, dt, load.foundation_velocity, 1, params_.initial_gap,
        disc_.mesh.contact_heights, touching, solver_.status(), [&](int i) { return contact_u_[i]; },
        [&](int i) { return 2 * bw_[i]; }, [&](int i, int) { return 2 * bw_[nc + i]; });

    ydot = 2 * c2 * w_ - ydot;
    y += 2 * w_;
    lift_rate = 2 * c2 * w_t - lift_rate;
    lift_at += du_t;
    top = load.top_end;
    top_rate = load.top_rate;
    s.time += dt;
    return report;
}

}  // namespace contactbody
